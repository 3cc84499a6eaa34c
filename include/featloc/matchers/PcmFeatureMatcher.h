#pragma once
#include <mrpt/config/CLoadableOptions.h>
#include <mrpt/core/bits_math.h>

#include <Eigen/Core>

#include <vector>

#include "featloc/features/LineEllipseExtractor.h"
#include "featloc/matchers/PcmMotionUpdate.h"
#include "featloc/matchers/ScanMatcher.h"

namespace featloc
{
/** Borges & Aldon, "Motion Estimation by Iterative 2-D Features Matching in
 * Range Images" (ICRA 2000): scans are reduced to infinite lines and
 * ellipsoidal clusters (LineEllipseExtractor) and matched with a
 * Possibilistic C-Means cost (eq. 9), alternating the memberships mu_ij
 * (eq. 14) and the closed-form motion (eqs. 16-23, PcmMotionUpdate).
 *
 * Iteration (section 4): eta_i = -d_max^2 / log 0.5 (eq. 25), d_max the
 * distance between the feature predicted at the estimate and at a corner
 * of the motion bounds (eq. 24: "the maximum is on its limits"; the
 * paper's one corner, or the largest over all 8: dmax_corners); bounds
 * shrink as
 * Delta_n = Delta_0 exp(-n / tau) up to n_s (eq. 26), tau per component so
 * that Delta_{n_s} = final_bounds; stop when the step is below
 * stop_translation and stop_rotation, or after max_iterations (n_max).
 * Initial bounds: bounds_sigmas standard deviations of the initial guess
 * (at least final_bounds), or initial_bounds from the configuration.
 *
 * Two additions of featloc's, both switchable (the benchmarks run both
 * ways):
 * - refinement = weighted: after the iterations, the motion minimising
 *   sum mu r^T C^-1 r on the converged pairs (Gauss-Newton), C the
 *   residual's covariance from both features' fit covariances. The paper's
 *   E weighs every foot-point residual alike, so it does not use that a
 *   long wall gives the rotation ten times better than a short line; the
 *   weighted step does. refinement = none keeps the paper's estimate.
 * - pair gate (pair_gate_chi2 > 0, 13.8 = 99.9% for 2 dof): a converged
 *   pair whose residual is implausible under C + H P H^T (P the estimate's
 *   covariance) is dropped and the estimate redone, up to three times.
 *   Without it, two pieces of one long wall seen from two viewpoints (each
 *   short enough to be an ellipsoidal cluster, but different parts of the
 *   wall) keep a sizeable membership and pull the estimate by centimetres.
 *
 * Covariance: the estimate solves sum mu H^T W r = 0 (W = I for the
 * paper's estimator, C^-1 after refinement), so its covariance is the
 * sandwich B^-1 S B^-1 with B = sum mu H^T W H (H = dr/d(t, w)) and S the
 * covariance of that sum from the features' fit covariances, summed per
 * feature because one feature takes part in several pairs.
 *
 * Failure: fewer than min_matched_features current features matched
 * (max_i mu_ij > 0.5), or the matched features leave a direction
 * (nearly) unconstrained: B singular, or the estimate's standard deviation
 * along its weakest translation direction above max_translation_sigma, or
 * in rotation above max_rotation_sigma. The reason names the direction
 * (e.g. along parallel corridor walls). */
class PcmFeatureMatcher : public ScanMatcher
{
	DEFINE_MRPT_OBJECT(PcmFeatureMatcher, featloc)

   public:
	/** With IDC (and its coarse search) as its fallback (fallback_class):
	 * PCM's features cannot place a scan along parallel walls; the points
	 * of a door jamb can, and IDC says when they cannot (MRPT's ICP, the
	 * fallback before, slid along a corridor instead: doc/benchmarks.md,
	 * "Issue 15, fourth session"). */
	PcmFeatureMatcher() : ScanMatcher("featloc::IdcMatcher") { m_fallbackAboveSigmaXY = 0.01; }

	struct Parameters : public mrpt::config::CLoadableOptions
	{
		LineEllipseExtractor::Parameters extraction;
		unsigned int max_iterations = 10;  //!< n_max
		unsigned int bound_iterations = 5;	//!< n_s
		/** Delta_{n_s}: x [m], y [m], w [rad] (file: m m deg). */
		std::vector<double> final_bounds = {0.1, 0.1, mrpt::DEG2RAD(1.0)};
		std::string initial_bounds_source = "covariance";  //!< or "config"
		std::vector<double> initial_bounds = {0.3, 0.3, mrpt::DEG2RAD(10.0)};
		double bounds_sigmas = 3;
		double stop_translation = 1e-4;	 //!< [m] epsilon_t
		double stop_rotation = mrpt::DEG2RAD(0.01);	 //!< [rad] epsilon_w
		unsigned int min_matched_features = 2;
		double max_translation_sigma = 0.1;	 //!< [m]
		double max_rotation_sigma = mrpt::DEG2RAD(3.0);	 //!< [rad]
		std::string refinement = "weighted";  //!< weighted | none
		double pair_gate_chi2 = 13.8;  //!< 0 disables the consistency gate
		/** d_max of eq. (24): "all" (featloc) the largest over the 8
		 * corners of the bounds box; "published" the one corner the paper
		 * writes, (t + Delta_t, w + Delta_w). */
		std::string dmax_corners = "all";
		/** The estimate stays within this many Delta_0 of the guess
		 * (featloc; the paper assumes the motion lies in the validity
		 * interval): rotation candidates of the closed form outside it are
		 * not considered (a pi - w flip won once in a symmetric room), and
		 * an estimate outside it fails. 0: neither, as published. */
		double motion_window_bounds = 2.0;
		/** featloc: failure when the estimate's Mahalanobis^2 from the
		 * initial guess exceeds this (ScanMatcher::guessGateChi2, as IDC's):
		 * along a corridor PCM took estimates 0.1-0.75 m off with
		 * a sigma of centimetres there (doc/pcm-matcher.md). 0: off, as
		 * published. */
		double guess_gate_chi2 = 21.1;

		void loadFromConfigFile(
			const mrpt::config::CConfigFileBase& c,
			const std::string& s) override;
		void saveToConfigFile(
			mrpt::config::CConfigFileBase& c,
			const std::string& s) const override;
	};

	Parameters params;

	/** Features of the last match (sensor frames), for inspection. */
	const std::vector<ScanFeature>& lastReferenceFeatures() const { return m_reference; }
	const std::vector<ScanFeature>& lastCurrentFeatures() const { return m_current; }

   protected:
	MatchInspection inspectOwnMatch(const ScanPoints& reference, const ScanPoints& current,
		const mrpt::poses::CPose2D& sensorEstimate) const override;
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
	double guessGateChi2() const override { return params.guess_gate_chi2; }

   private:
	/** Steps 2-4 of section 4: eta_i from the bounds, mu_ij for every
	 * same-kind pair (pairs with negligible mu are left out). */
	void memberships(const mrpt::math::TPose2D& x, const double bounds[3]);
	/** Covariance-weighted Gauss-Newton on the current pairs. */
	mrpt::math::TPose2D refine(const mrpt::math::TPose2D& start) const;
	/** Drops implausible pairs; returns how many. */
	size_t gate(const mrpt::math::TPose2D& x, const mrpt::math::CMatrixDouble33& cov);
	/** Sandwich covariance; false with a reason when degenerate. */
	bool covariance(
		const mrpt::math::TPose2D& x, mrpt::math::CMatrixDouble33& cov,
		std::string& reason) const;

	LineEllipseExtractor m_extractor;
	std::vector<ScanFeature> m_reference, m_current;  // reused buffers
	std::vector<FeaturePair> m_pairs;
	mutable std::vector<Eigen::Matrix<double, 3, 2>> m_perCurrent, m_perReference;
};
}  // namespace featloc
