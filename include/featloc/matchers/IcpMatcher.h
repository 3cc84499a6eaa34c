#pragma once
#include <mrpt/config/CLoadableOptions.h>
#include <mrpt/core/bits_math.h>
#include <mrpt/slam/CICP.h>

#include "featloc/matchers/ScanMatcher.h"

namespace featloc
{
/** Baseline matcher: MRPT's own ICP (mrpt::slam::CICP, classic or
 * Levenberg-Marquardt) between the two scans' point clouds. Every other
 * featloc matcher is compared against this one.
 *
 * The covariance is CICP's (finite differences or linear MSE, scaled by
 * covariance_varPoints). The match fails when fewer than minGoodness of the
 * current scan's points end up paired. */
class IcpMatcher : public ScanMatcher
{
	DEFINE_MRPT_OBJECT(IcpMatcher, featloc)

   public:
	struct Parameters : public mrpt::config::CLoadableOptions
	{
		mrpt::slam::TICPAlgorithm algorithm = mrpt::slam::icpClassic;
		mrpt::slam::TICPCovarianceMethod covarianceMethod =
			mrpt::slam::icpCovFiniteDifferences;
		unsigned int maxIterations = 80;  //!< per threshold level
		double minAbsStep_trans = 1e-6;	 //!< [m] convergence step
		double minAbsStep_rot = mrpt::DEG2RAD(1e-4);  //!< [rad] convergence step
		double thresholdDist = 0.5;	 //!< [m] initial pairing distance
		double thresholdAng = 0.0;	//!< [rad] extra distance per metre of range
		double ALFA = 0.8;	//!< threshold shrink factor on convergence
		double smallestThresholdDist = 0.1;  //!< [m] finest pairing distance
		bool onlyUniqueRobust = false;	//!< one pairing per reference point
		unsigned int corresponding_points_decimation = 1;  //!< 1 = every point
		double covariance_varPoints = 0.02 * 0.02;	//!< [m^2] point noise
		bool use_kernel = true;	 //!< Cauchy kernel in the covariance
		double kernel_rho = 0.07;  //!< [m]
		double Axy_aprox_derivatives = 0.05;  //!< [m] LM only
		double LM_initial_lambda = 1e-4;  //!< LM only
		double minDistBetweenPoints = 0.0;	//!< [m] decimation, 0 = off
		double minGoodness = 0.4;  //!< failure below this paired fraction

		void loadFromConfigFile(
			const mrpt::config::CConfigFileBase& c,
			const std::string& s) override;
		void saveToConfigFile(
			mrpt::config::CConfigFileBase& c,
			const std::string& s) const override;
		/** The equivalent mrpt::slam::CICP options. */
		mrpt::slam::CICP::TConfigParams toCICP() const;
	};

	Parameters params;

	/** MRPT's ICP as MRPT runs it, the peer featloc is measured against:
	 * the wide-basin search that every featloc matcher runs by default is
	 * off here unless `coarse_search = true`. With it on, the search
	 * always runs (`coarse_confirm_share` 0): skipping it needs a
	 * covariance that grows along a corridor, and MRPT's ICP reports 16 mm
	 * there (CorrelativeScanSearchTest, the corridor). */
	IcpMatcher()
	{
		coarseSearchOptions().enabled = false;
		coarseSearchOptions().confirmShare = 0;
		m_dequantizeRanges = false;
	}

   protected:
	void loadOwnParams(
		const mrpt::config::CConfigFileBase& cfg,
		const std::string& section) override;
	void saveOwnParams(
		mrpt::config::CConfigFileBase& cfg,
		const std::string& section) const override;
	void matchPoints(
		const ScanPoints& reference, const ScanPoints& current,
		const mrpt::poses::CPosePDFGaussian& initialGuess,
		MatchResult& result) override;
};

}  // namespace featloc
