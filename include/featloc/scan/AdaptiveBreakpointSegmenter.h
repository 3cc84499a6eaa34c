#pragma once
#include <mrpt/config/CLoadableOptions.h>
#include <mrpt/core/bits_math.h>

#include <vector>

#include "featloc/scan/ScanPoints.h"
#include "featloc/scan/ScanSegment.h"

namespace featloc
{
/** Borges & Aldon's adaptive breakpoint detector, the segmentation of
 * Nunez et al.'s CF-IDC (CF-SMA1, eq. 3): consecutive points p_{i-1}, p_i
 * (bearing order) belong to different segments when
 *
 *   ||p_i - p_{i-1}|| > r_{i-1} sin(dphi) / sin(lambda - dphi) + 3 sigma_r
 *
 * dphi being the bearing difference of the two points (the angular
 * resolution, or more where invalid beams lie between them). The first
 * term is how far apart two consecutive points can be on a surface seen at
 * an incidence as grazing as lambda; the second covers the range noise.
 * Where dphi >= lambda the bound is infinite in the paper's geometry; such
 * a gap (a sector of missing returns) is always a breakpoint here.
 *
 * featloc: with breakAtMissingReturns, any beam without a return between
 * two points is a breakpoint. A surface between them within range would
 * have returned it, and eq. (3) with dphi grown by the missing beams lets
 * almost anything through: two points near the range limit on either
 * side of a recess became one "surface" across its opening, whose local
 * line put a corridor's matches 10 cm off along it. A beam lost on a
 * surface (a dropout) splits that surface in two, which costs little.
 *
 * featloc: with sigmaFromScan, sigma_r is at least the scan's own range
 * noise (PointNoiseEstimator::rangeNoise over the whole scan, chords of 10
 * cm; corners and depth jumps are outliers to its median). With a fixed
 * 5 mm a 0.25 deg Hokuyo at 3 cm noise had its walls cut into segments of
 * a few points (neighbours 4 cm apart in range against a 4 cm bound), too
 * short for any local line to know its direction.
 *
 * Every point ends in exactly one segment (isolated points are one-point
 * segments): the IDC reference polyline joins consecutive points of a
 * segment only; CF-IDC drops segments that are too small itself. */
class AdaptiveBreakpointSegmenter
{
   public:
	struct Parameters : public mrpt::config::CLoadableOptions
	{
		double lambda = mrpt::DEG2RAD(10.0);  //!< [rad] lambda of eq. (3)
		double sigma_r = 0.005;	 //!< [m] sigma_r of eq. (3)
		bool breakAtMissingReturns = true;	//!< featloc (false: the paper)
		bool sigmaFromScan = false;	 //!< featloc (IDC and CF-IDC turn it on; doc/config-reference.md)

		bool operator==(const Parameters& o) const
		{
			return lambda == o.lambda && sigma_r == o.sigma_r &&
				breakAtMissingReturns == o.breakAtMissingReturns &&
				sigmaFromScan == o.sigmaFromScan;
		}

		void loadFromConfigFile(
			const mrpt::config::CConfigFileBase& c,
			const std::string& s) override;
		void saveToConfigFile(
			mrpt::config::CConfigFileBase& c,
			const std::string& s) const override;
	};

	AdaptiveBreakpointSegmenter() = default;
	explicit AdaptiveBreakpointSegmenter(const Parameters& p) : params(p) {}

	/** Segments `points` (all of them, in order) into `out`. */
	void segment(const ScanPoints& points, std::vector<ScanSegment>& out) const;

	/** True when eq. (3) puts a breakpoint between points a and b (b after
	 * a), with params.sigma_r (or, after segment(), the sigma_r it used). */
	bool isBreakpoint(const ScanPoint& a, const ScanPoint& b) const;

	/** The sigma_r the last segment() used [m]. */
	double lastSigmaR() const { return m_sigmaR >= 0 ? m_sigmaR : params.sigma_r; }

	Parameters params;

   private:
	mutable double m_lastDphi = -1, m_lastRatio = 0;  // eq. (3) for the last dphi
	mutable double m_sigmaR = -1;  // segment()'s sigma_r (-1: params.sigma_r)
};
}  // namespace featloc
