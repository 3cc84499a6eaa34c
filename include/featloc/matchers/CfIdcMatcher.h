#pragma once
#include <mrpt/config/CLoadableOptions.h>

#include <string>
#include <vector>

#include "featloc/features/CurvatureFunction.h"
#include "featloc/features/CurvatureFunctionMatcher.h"
#include "featloc/matchers/IterativeDualCorrespondence.h"
#include "featloc/matchers/ReferencePolyline.h"
#include "featloc/matchers/ScanMatcher.h"
#include "featloc/scan/AdaptiveBreakpointSegmenter.h"

namespace featloc
{
/** Nunez, Vazquez-Martin, Bandera & Sandoval, "CF-IDC: a robust robot's
 * self-localization in dynamic environments using curvature information":
 * IDC on only those points of the two scans that belong to segments whose
 * shapes match, so that people and objects that moved between the scans
 * do not pull the estimate.
 *
 *  CF-SMA1: both scans are cut into segments by the adaptive breakpoint
 *           detector (eq. 3, AdaptiveBreakpointSegmenter); segments of
 *           fewer than min_segment_points are dropped ("isolated groups");
 *           each remaining segment gets its adaptive curvature function
 *           (eqs. 4-6, CurvatureFunction).
 *  CF-SMA2: curvature functions are paired by the FFT correlation of
 *           eq. (7), greedily above U_c (CurvatureFunctionMatcher); the
 *           points of unpaired segments, in both scans, are dropped.
 *  CF-SMA3: IDC (IterativeDualCorrespondence) on the kept points.
 *
 * featloc's additions, each switchable (pairing_gate = false,
 * segment_gate = 0 and the IDC's final_phase = idc give the paper):
 * - pairing_gate: only segments that can be the same object under the
 *   initial guess are compared (their bounding boxes, the current one
 *   moved by the guess, no farther apart than window_sigmas times the
 *   guess's uncertainty at the segment's farthest point). Curvature ignores
 *   position: without the gate a straight piece of one wall pairs as
 *   readily with any other straight wall;
 * - segment_gate: a person who walked half a metre still has the shape of
 *   a person, and a wall seen from a little further along has a different
 *   normalised curvature function. So when IDC's dual rules have brought
 *   the estimate near the solution (at the switch to the point-to-line
 *   phase), the segments are chosen again by geometry: every segment of
 *   the current scan, small ones included, is kept if, at the estimate,
 *   the median distance of its points to the reference (all its segments)
 *   is at most twice segment_gate, and dropped otherwise ("moved"); the
 *   point-to-line phase runs on those, and once it has converged the test
 *   is made again with segment_gate itself (the iterations go on if that
 *   drops anything). The looser first test leaves the few points that fix
 *   a weak direction (a door jamb of three points along a corridor) to be
 *   judged by an estimate that is right along it;
 * - segment_residual_chi2 (with the segment gate, in its final test): a
 *   door that turned a few degrees, a cart pushed a few centimetres, lie
 *   within the gate and keep their shape; their points' residuals at the
 *   estimate do not (SegmentResidualTest: an offset and a slope along the
 *   segment, chi-square of tens of sigmas). The segments above the
 *   threshold are dropped too, most discordant first, as long as what is
 *   dropped stays under a third of the kept points (the static majority,
 *   which the estimate follows, is not judged by the minority).
 * If the curvature pairing keeps less than a third of the points of the
 * segments large enough (or fewer than 3 min_pairs), IDC starts from all of
 * them (pairing_fallback; reported as the reason and in
 * MatchResult::matcherFallback); if the segment gate would leave fewer than
 * 3 min_pairs points, the estimate is too poor to judge by and the
 * pairing's choice stands.
 *
 * For the ablation of the curvature stage, curvature_pairing = false skips
 * CF-SMA2: every segment large enough goes to IDC (the gates still act).
 *
 * What was dropped, and why, is reported per segment (lastCurrentSegments,
 * lastReferenceSegments) for the tests and for pictures. */
class CfIdcMatcher : public ScanMatcher
{
	DEFINE_MRPT_OBJECT(CfIdcMatcher, featloc)

   public:
	/** A failed (or, with fallback_on_ambiguity, ambiguous) CF-IDC match
	 * is made by IDC on the whole scans by default (fallback_class): on
	 * the real logs CF-IDC's segments leave the motion unconstrained where
	 * IDC's points do not (doc/benchmarks.md, "Issue 15, thirteenth
	 * session"). The paper has none: fallback_class empty.
	 * A match that fails only because its segments leave one direction
	 * free goes to that fallback too (free_direction_from_guess false
	 * here): IDC keeps the guess along the direction its own points leave
	 * free, and fixes the other two from the whole scans, where CF-IDC's
	 * segments gave heading errors of 0.4-0.6 deg at the corridor's turn
	 * and a matcher chain 3.5 times IDC's (doc/benchmarks.md, "Issue 15,
	 * fourteenth session"). */
	// The confirmation probe ungated, as IdcMatcher's.
	CfIdcMatcher() : ScanMatcher("featloc::IdcMatcher", false)
	{
		coarseSearchOptions().confirmProbeSigma = 0;
	}

	struct Parameters : public mrpt::config::CLoadableOptions
	{
		// featloc, as in IdcMatcher: sigma_r at least the scan's own range
		// noise (breakpoint_sigma_r_from_scan = false: the paper).
		Parameters() { segmentation.sigmaFromScan = true; }

		AdaptiveBreakpointSegmenter::Parameters segmentation;
		unsigned int min_segment_points = 5;
		CurvatureFunction::Parameters curvature;
		CurvatureFunctionMatcher::Parameters correlation;
		/** false: no CF-SMA2, every segment of min_segment_points goes to
		 * IDC (an ablation switch: what the curvature stage itself does). */
		bool curvature_pairing = true;
		bool pairing_gate = true;
		/** The pairing keeps under a third of the points: IDC starts from
		 * every segment large enough (false: the paper, IDC on the paired
		 * ones). Counted (MatchResult::matcherFallback). */
		bool pairing_fallback = true;
		double segment_gate = 0.05;	 //!< [m] 0 disables
		/** The segment gate is at least the step of the current scan's
		 * range lattice (RangeLattice), which can put a static segment
		 * that far off the reference at the true motion (false: the fixed
		 * segment_gate alone, an ablation). */
		bool segment_gate_from_lattice = true;
		/** Chi-square (2 dof) of a kept segment's residual offset and slope
		 * at the estimate above which the final segment gate drops it as
		 * moved (SegmentResidualTest); 0: off. */
		double segment_residual_chi2 = 200;
		IterativeDualCorrespondence::Parameters idc;

		void loadFromConfigFile(
			const mrpt::config::CConfigFileBase& c,
			const std::string& s) override;
		void saveToConfigFile(
			mrpt::config::CConfigFileBase& c,
			const std::string& s) const override;
	};

	/** One segment of a scan and what became of it. */
	struct SegmentReport
	{
		ScanSegment segment;  //!< indices into the scan's valid points
		bool kept = false;
		int pairedWith = -1;  //!< curvature partner in the other scan, or -1
		double similarity = 0;	//!< rho of the pair (best rho if unpaired)
		std::string reason;	 //!< why it was dropped, or how it was kept
	};

	Parameters params;

	const std::vector<SegmentReport>& lastCurrentSegments() const { return m_currentReport; }
	const std::vector<SegmentReport>& lastReferenceSegments() const { return m_referenceReport; }

   protected:
	MatchInspection inspectOwnMatch(const ScanPoints& reference, const ScanPoints& current,
		const mrpt::poses::CPose2D& sensorEstimate) const override;
	void loadOwnParams(
		const mrpt::config::CConfigFileBase& cfg,
		const std::string& section) override;
	void saveOwnParams(
		mrpt::config::CConfigFileBase& cfg,
		const std::string& section) const override;
	double guessGateChi2() const override { return params.idc.guess_gate_chi2; }
	bool usesRangeLatticeStep() const override
	{
		return params.segment_gate > 0 && params.segment_gate_from_lattice;
	}
	void matchPoints(
		const ScanPoints& reference, const ScanPoints& current,
		const mrpt::poses::CPosePDFGaussian& initialGuess,
		MatchResult& result) override;

   private:
	/** CF-SMA1 for one scan whose segments are in `report`: the curvature
	 * functions of those large enough; segmentOf[f] is the report index of
	 * function f. */
	void describe(
		const ScanPoints& scan, std::vector<SegmentReport>& report,
		std::vector<std::vector<double>>& functions, std::vector<int>& segmentOf);
	/** pairing_gate: which (current, reference) function pairs may be the
	 * same object under the guess. */
	void plausiblePairs(
		const ScanPoints& reference, const ScanPoints& current,
		const mrpt::poses::CPosePDFGaussian& guess);
	/** CF-SMA2's verdicts in the reports. */
	void pairSegments();
	/** segment_gate, at the estimate x: the reference becomes all its
	 * segments, the current scan those lying within `gate` of it (median),
	 * and, with testResiduals, whose residuals do not say they moved.
	 * True if that changed the sets. */
	bool reselect(
		const ScanPoints& reference, const ScanPoints& current, const mrpt::math::TPose2D& x,
		double gate, bool testResiduals);
	/** segment_residual_chi2: drops the kept current segments whose
	 * residuals at x say they moved (at most kMaxMovedShare of the kept
	 * points, most discordant first). */
	void dropMovedByResiduals(const ScanPoints& current, const mrpt::math::TPose2D& x);
	static constexpr double kMaxMovedShare = 1.0 / 3.0;
	/** How the reason of a segment dropped by its residuals starts. */
	static constexpr const char* kMovedByResiduals = "moved: its residuals";
	/** The reference polyline of the reference segments marked kept. */
	void buildReference(const ScanPoints& reference);
	/** The current points of the segments marked kept. */
	void collectKeptCurrent(const ScanPoints& current);

	AdaptiveBreakpointSegmenter m_segmenter;
	CurvatureFunction m_curvature;
	CurvatureFunctionMatcher m_correlator;
	IterativeDualCorrespondence m_idc;
	ReferencePolyline m_polyline;
	std::vector<SegmentReport> m_currentReport, m_referenceReport;
	std::vector<std::vector<double>> m_currentFunctions, m_referenceFunctions;
	std::vector<int> m_currentSegmentOf, m_referenceSegmentOf;
	std::vector<char> m_allowed;
	std::vector<ScanSegment> m_segments;
	std::vector<CurvatureFunctionMatcher::Match> m_matches;
	std::vector<ScanPoint> m_kept;
	double m_curvatureStep = 0;	 //!< metric sampling step of this match [m]
};
}  // namespace featloc
