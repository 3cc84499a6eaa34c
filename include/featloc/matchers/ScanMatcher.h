#pragma once
#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/obs/obs_frwds.h>
#include <mrpt/poses/CPosePDFGaussian.h>
#include <mrpt/rtti/CObject.h>

#include <memory>
#include <string>

#include "featloc/matchers/CorrelativeScanSearch.h"
#include "featloc/matchers/MatchInspection.h"
#include "featloc/matchers/MatchResult.h"
#include "featloc/scan/AdaptiveBreakpointSegmenter.h"
#include "featloc/scan/RangeLattice.h"
#include "featloc/scan/ScanPoints.h"

namespace featloc
{
/** Base of every scan matcher: estimates the motion between two 2-D range
 * scans from an initial guess with its uncertainty.
 *
 * Matchers are MRPT RTTI classes, created by name from the configuration
 * (`[ScanMatcher] class = featloc::IcpMatcher`, see ScanMatcherFactory) and
 * reading their parameters from their own section
 * (`[ScanMatcher.IcpMatcher]`).
 *
 * Frames: match() takes and returns robot-frame motions. It converts the
 * scans to their sensor frames (ScanPoints), converts the guess with the
 * scans' sensorPose, calls matchPoints(), and converts the result (mean and
 * covariance) back. Subclasses implement matchPoints() only, in the sensor
 * frame, on bearing-ordered valid points.
 *
 * The wide basin (issue "scan matchers that hold up"): unless
 * `coarse_search = false`, every matcher's iterations start from the best
 * pose of a correlative search over the guess's window
 * (CorrelativeScanSearch), and a match whose search finds too little overlap
 * or two distinct solutions, or whose iterations leave the search's solution,
 * fails with the reason instead of returning a confident wrong answer. */
class ScanMatcher : public mrpt::rtti::CObject
{
	DEFINE_VIRTUAL_MRPT_OBJECT(ScanMatcher)

   public:
	~ScanMatcher() override = default;

	/** Reads this matcher's parameters from `section` (the coarse search's
	 * `coarse_*` keys and the matcher's own); unspecified keys keep their
	 * defaults. Throws ConfigError on a bad value. */
	void loadParams(const mrpt::config::CConfigFileBase& cfg, const std::string& section);

	/** Writes every parameter, with its unit and meaning as a comment. */
	void saveParams(mrpt::config::CConfigFileBase& cfg, const std::string& section) const;

	/** The matcher that takes over when this one fails (`fallback_class`;
	 * null when none). */
	const std::shared_ptr<ScanMatcher>& fallback() const { return m_fallback; }

	/** The wide-basin stage's parameters (`coarse_*` keys). */
	CorrelativeScanSearch::Options& coarseSearchOptions() { return m_coarse.options; }
	const CorrelativeScanSearch::Options& coarseSearchOptions() const { return m_coarse.options; }

	/** Whether match() applies guessGateChi2() (default true), the
	 * fallback's included. Off for a matcher whose caller gates the
	 * estimate itself against the same prediction (MapLocalizer's map
	 * matches: [Localization] gate_chi2, map_guess_gate). */
	void setGuessGateEnabled(bool on) { m_guessGateEnabled = on; }
	bool guessGateEnabled() const { return m_guessGateEnabled; }

	/** Motion of the robot from the reference scan to the current scan.
	 * \param initialGuess robot-frame motion guess (e.g. the odometry
	 *        increment) with its covariance.
	 * \param gateAllowance robot-frame covariance the guess gate adds to
	 *        the guess's (not given to the matcher, kept in the result for
	 *        the EKF's gate): an error of the guess that does not belong
	 *        in its covariance (OdometrySamplingOffset).
	 * The result's timeSeconds covers the whole call. */
	MatchResult match(
		const mrpt::obs::CObservation2DRangeScan& reference,
		const mrpt::obs::CObservation2DRangeScan& current,
		const mrpt::poses::CPosePDFGaussian& initialGuess,
		const mrpt::math::CMatrixDouble33& gateAllowance = {});

	/** Same, on points already in a common frame (no sensor offsets). */
	MatchResult match(
		const ScanPoints& reference, const ScanPoints& current,
		const mrpt::poses::CPosePDFGaussian& initialGuess);

	/** What the last match() used, for the viewer (MatchInspection), given
	 * that match's scans as points in their sensor frames and its estimate
	 * in the sensor frames (S1^-1 (+) X (+) S2): the fallback's, when the
	 * fallback made that match (inspectOwnMatch). */
	MatchInspection inspectLastMatch(const ScanPoints& reference, const ScanPoints& current,
		const mrpt::poses::CPose2D& sensorEstimate) const;
	static constexpr double kInspectionPairDistance = 0.3;	//!< [m]

	/** The registered class name, e.g. "featloc::IcpMatcher". */
	std::string className() const;

   protected:
	/** `defaultFallbackClass`: the fallback_class of a matcher whose
	 * configuration does not name one (PCM and CF-IDC: IDC);
	 * `defaultFreeDirectionFromGuess`: its free_direction_from_guess. */
	explicit ScanMatcher(
		std::string defaultFallbackClass = {}, bool defaultFreeDirectionFromGuess = true)
		: m_fallbackClass(std::move(defaultFallbackClass)),
		  m_freeDirectionFromGuess(defaultFreeDirectionFromGuess)
	{
	}

	/** inspectLastMatch() of a match this matcher made. The default pairs
	 * each current point with its nearest reference point at the estimate
	 * (within kInspectionPairDistance); matchers that keep their own
	 * pairs, features or segments report those. */
	virtual MatchInspection inspectOwnMatch(const ScanPoints& reference,
		const ScanPoints& current, const mrpt::poses::CPose2D& sensorEstimate) const;

	/** The matcher's own parameters (the paper's and featloc's additions). */
	virtual void loadOwnParams(
		const mrpt::config::CConfigFileBase& cfg, const std::string& section) = 0;
	virtual void saveOwnParams(
		mrpt::config::CConfigFileBase& cfg, const std::string& section) const = 0;

	/** Matchers that reject estimates implausibly far from the initial
	 * guess return the Mahalanobis^2 threshold (0: no check). match()
	 * applies it in the robot frame, with the guess's and the estimate's
	 * covariances summed, and reports the distance. */
	virtual double guessGateChi2() const { return 0; }

	/** Implemented by each matcher. `initialGuess` and the result are the
	 * pose of `current`'s frame in `reference`'s frame. Must fill estimate,
	 * success (with failureReason), iterations, goodness. Must not throw on
	 * degenerate input (empty scans, too few points): report failure. */
	virtual void matchPoints(
		const ScanPoints& reference, const ScanPoints& current,
		const mrpt::poses::CPosePDFGaussian& initialGuess,
		MatchResult& result) = 0;

	/** The step of the range lattice the current scan's readings sat on
	 * (RangeLattice) in the match being made, 0 when none or not looked
	 * for (looked for with dequantize_ranges, or usesRangeLatticeStep());
	 * with dequantize_ranges its points were dequantized before
	 * matchPoints(). Set by the match() of observations; 0 in the match()
	 * of points, which are matched as they are. */
	double rangeLatticeStep() const { return m_rangeLatticeStep; }
	/** `p` for this match's scans: a range lattice left in the readings
	 * (not dequantized) is not range noise, so eq. (3)'s sigma_r is not
	 * estimated from them (its steps would widen every bound by 3 x step /
	 * sqrt(12) and join surfaces across their depth jumps). */
	AdaptiveBreakpointSegmenter::Parameters segmentationFor(
		AdaptiveBreakpointSegmenter::Parameters p) const
	{
		if (latticeLeftInReadings()) p.sigmaFromScan = false;
		return p;
	}
	/** The same for the direction sigma local lines grow to
	 * (grow_lines_to_direction_sigma): on a lattice left in the readings the
	 * range noise estimated from them is the lattice's, and lines grown to
	 * it span its arcs. 0: no growth. */
	double lineGrowthTargetFor(double target) const
	{
		return latticeLeftInReadings() ? 0.0 : target;
	}
	/** The same for max_face_direction_sigma (0: off): on a lattice left
	 * in the readings a long segment's short lines are the lattice's arcs,
	 * not faces, and paired they held a match at zero motion
	 * (CfIdcMatcher.ARangeLatticeNoLongerHoldsTheMatchAtZeroMotion). */
	double faceDirectionSigmaFor(double sigma) const { return latticeLeftInReadings() ? 0.0 : sigma; }
	/** This match's scans hold a range lattice that was not undone. */
	bool latticeLeftInReadings() const { return m_rangeLatticeStep > 0 && !m_dequantizeRanges; }
	/** The least range noise [m] a covariance of this match may assume:
	 * the lattice's cell, rangeLatticeStep() / sqrt(12) (0 without one).
	 * Readings put back on their surfaces lie nearer than that, but their
	 * errors are shared along each run, which a per-point sigma or a
	 * scan's scatter cannot show. (Readings kept on their level carry
	 * their shared error themselves: ScanPoint::sharedErrorGroup.) */
	double rangeLatticeCellSigma() const;
	/** Whether matchPoints() reads rangeLatticeStep(). */
	virtual bool usesRangeLatticeStep() const { return false; }
	/** `dequantize_ranges` (true; IcpMatcher: false). */
	bool m_dequantizeRanges = true;
	/** `fallback_above_sigma_xy` [m] (0: off; PcmFeatureMatcher: 0.01). */
	double m_fallbackAboveSigmaXY = 0;

   private:
	/** matchPoints(), its success turned into a failure of kind
	 * "non_finite" where the estimate or its covariance is not finite. */
	void matchPointsFinite(const ScanPoints& reference, const ScanPoints& current,
		const mrpt::poses::CPosePDFGaussian& initialGuess, MatchResult& result);
	/** The lattice of `scan`'s readings (the scan before it too, the
	 * previous call's, is remembered: in a sequence each scan is matched
	 * as current and then as reference), undone if dequantize_ranges.
	 * Returns the step (0: none). */
	double undoRangeLattice(ScanPoints& scan);

	/** loadParams(); `followFallback` false for a fallback itself, whose
	 * own fallback_class is read but not followed (one level: no cycle). */
	void loadParams(const mrpt::config::CConfigFileBase& cfg, const std::string& section,
		bool followFallback);

	/** A failed match `r` handed to the fallback (`run` makes the
	 * fallback's match from the same input): its result, which says whose
	 * it is (MatchResult::primaryFailure), or `r` when no fallback applies.
	 * A failure for too few points stays: no matcher can do better. With
	 * fallback_on_ambiguity, an ambiguous `r` goes to the fallback too and
	 * is replaced only by a success that is not ambiguous; so does, with
	 * fallback_above_sigma_xy, a weak one (weakTranslationSigma()). */
	template <typename Run>
	MatchResult tryFallback(MatchResult r, Run&& run);
	/** With fallback_above_sigma_xy: the largest translation sigma [m] of a
	 * successful, unflagged `r` when it exceeds both that key and the range
	 * lattice's cell (rangeLatticeCellSigma(), which floors every match's
	 * covariance on a lattice and so says nothing of its geometry); else 0. */
	double weakTranslationSigma(const MatchResult& r) const;

	/** Point checks, the coarse search over `window`'s 3 sigma (the guess
	 * with the gate allowance) and matchPoints(); no timing, no guess
	 * check. */
	MatchResult matchInSensorFrames(
		const ScanPoints& reference, const ScanPoints& current,
		const mrpt::poses::CPosePDFGaussian& initialGuess,
		const mrpt::poses::CPosePDFGaussian& window);
	/** With coarse_confirm_share > 0: the iterations from the guess, kept
	 * in `r` (true) when they succeed at a pose the reference confirms
	 * (ReferenceOverlap) and no pose slid within the search's `window`
	 * fits as well (coarse_confirm_probe); false leaves `r` as it was, for
	 * the search. */
	bool matchConfirmedFromGuess(const ScanPoints& reference, const ScanPoints& current,
		const mrpt::poses::CPosePDFGaussian& initialGuess,
		const mrpt::poses::CPosePDFGaussian& window, MatchResult& r);
	/** The iterations from the coarse search's solution, and the check that
	 * they stay on it. */
	void matchFromCoarseSearch(const ScanPoints& reference, const ScanPoints& current,
		const mrpt::poses::CPosePDFGaussian& window, MatchResult& r);
	/** coarse_refine_rivals: the rivals of `amb` from which the matcher's
	 * iterations (started at the rival, with the search's grid
	 * covariance) do not come back to r's estimate (or fail), with their
	 * reasons; the matcher's state is left as r's own iterations left it. */
	CorrelativeScanSearch::Ambiguity rivalsOfTheirOwn(const ScanPoints& reference,
		const ScanPoints& current, const CorrelativeScanSearch::Result& coarse,
		const CorrelativeScanSearch::Ambiguity& amb, const MatchResult& r);

	/** free_direction_from_guess: a match that failed only because the
	 * points leave one direction free (MatchResult::freeDirection, a
	 * corridor) takes the guess's position along it, fused with the
	 * little the points say there as one scalar Kalman update, and the
	 * matcher's across it; it becomes a success flagged ambiguous. */
	static void keepGuessAlongFreeDirection(
		const mrpt::poses::CPosePDFGaussian& window, MatchResult& r);
	/** A guess-gate rejection (r.rejectedByGuessGate) put to the scans:
	 * the odometry can be wrong by more than its covariance (a reading
	 * taken long before the scan), and then the gate throws a good match
	 * away. A correlative search over the widest window
	 * (coarse_max_window_*) around `guess` (in the sensor frames, as
	 * `estimate`) must find `estimate` as its best, no rival the points
	 * do not reject (CorrelativeScanSearch::ambiguity), and paired evidence
	 * for the estimate over the guess of at least coarse_overrule_guess_z;
	 * then the match succeeds, marked guessGateOverruled. Otherwise the
	 * rejection stands. */
	void arbitrateGuessGate(const ScanPoints& reference, const ScanPoints& current,
		const mrpt::poses::CPose2D& guess, const mrpt::poses::CPose2D& estimate, MatchResult& r);
	CorrelativeScanSearch m_coarse;
	std::string m_fallbackClass;  //!< `fallback_class` as written ("" none)
	bool m_guessGateEnabled = true;	 //!< setGuessGateEnabled()
	std::shared_ptr<ScanMatcher> m_fallback;
	bool m_followFallback = true;  //!< false for a fallback itself
	bool m_fallbackOnAmbiguity = true;	//!< `fallback_on_ambiguity`
	bool m_fallbackSharesTables = true;	 //!< `fallback_shares_tables`
	bool m_freeDirectionFromGuess;	//!< `free_direction_from_guess`
	bool m_lastMatchByFallback = false;	 //!< for inspectLastMatch()
	RangeLattice m_lattice;
	ScanPoints m_latticeScan;  //!< the last scan undoRangeLattice() looked at
	double m_latticeScanStep = 0, m_latticeScanOffset = 0;	//!< its lattice
	double m_rangeLatticeStep = 0;	//!< rangeLatticeStep()
	void checkAgainstGuess(const mrpt::poses::CPosePDFGaussian& guess, MatchResult& r) const;
};

}  // namespace featloc
