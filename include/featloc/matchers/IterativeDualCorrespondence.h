#pragma once
#include <mrpt/config/CLoadableOptions.h>
#include <mrpt/core/bits_math.h>
#include <mrpt/math/TPose2D.h>
#include <mrpt/poses/CPosePDFGaussian.h>

#include <Eigen/Core>
#include <functional>
#include <string>
#include <vector>

#include "featloc/matchers/PointToLineCovariance.h"
#include "featloc/matchers/ReferencePolyline.h"
#include "featloc/scan/ScanPoints.h"

namespace featloc
{
/** Lu & Milios' Iterative Dual Correspondence ("Robot pose estimation in
 * unknown environments by matching 2D range scans", 1997), the scan
 * matcher of Nunez et al.'s CF-IDC stage CF-SMA3 and its baseline.
 *
 * Each iteration k, with the current points moved by the estimate x:
 *  1. closest-point pairs (the ICP rule): each point with the nearest point
 *     of the reference polyline (ReferencePolyline, interpolated on edges)
 *     within D_k;
 *  2. matching-range pairs (the IMRP rule): each point with the polyline
 *     point of the closest range within +-B_k of its bearing, kept when
 *     the two are within D_k (so the window need not reach beyond
 *     asin(D_k / range) either);
 *  3. (w1, T1), the least-squares motion of the closest-point pairs, and
 *     (w2, T2), that of the matching-range pairs; x <- (w2, T1) (+) x: the
 *     rotation of the range rule, the translation of the closest-point
 *     rule, as Lu & Milios combine them.
 * B_k and D_k shrink geometrically from B_0 and D_0 (window_sigmas
 * standard deviations of the initial guess; D_0 includes the rotation's
 * effect at the median range) to their minima, reached at
 * k = window_iterations: the bearing window bounds how much rotation the
 * range rule can see, and pairs farther apart than D_k are outliers.
 * Convergence, as in the paper (section III.C): the mean squared
 * closest-point distance changes by less than error_ratio (1e-6 =
 * 0.0001 %) relative; once the windows are at their minima, also when it
 * equals (by the same test) the error of two to eight iterations back (a
 * correspondence flipping between edges at a corner makes the iteration
 * cycle through two or three estimates microns apart for ever) or when the
 * estimate stops moving (steps below 1e-7 m and 1e-7 rad). After
 * max_iterations (500) the match fails ("no convergence").
 *
 * final_phase = point_to_line (featloc's addition, switchable): the
 * windows also shrink to window_sigmas times what the last dual step moved
 * (no wider than what is left to find), and once they have reached their
 * minima the iterations continue with
 * Gauss-Newton steps on the point-to-line error of the closest-point pairs
 * (rotation and translation jointly, as Censi's PLICP) instead of step 3,
 * until the same convergence test holds or a step is shorter than
 * step_tolerance standard deviations of the estimate (the re-paired
 * point-to-line iteration can otherwise cycle for ever through estimates a
 * tenth of a millimetre apart). The dual rules bring the
 * estimate from far away; near the solution their fixed point converges
 * only linearly (the range rule's rotation and the closest-point
 * translation trade off along walls) and is biased by the range rule's
 * interpolation. The point-to-line minimum converges in a few steps and is
 * what the covariance below describes. final_phase = idc is the paper.
 *
 * The point-to-line error uses each reference edge's local line
 * (ReferencePolyline::LocalLine, fitted to the edge and its neighbours on
 * the same surface) and only lines of three points or more: a two-point
 * edge whose neighbours both leave its line bridges two surfaces (a depth
 * jump at long range that eq. (3) lets through) and would bias the
 * estimate by centimetres.
 *
 * Covariance: Censi's closed form for the point-to-line error at the
 * estimate (PointToLineCovariance), the range noise estimated from the
 * residuals (at least min_range_sigma), times covariance_inflation. Censi's
 * formula holds the correspondences fixed; re-pairing noisy points at each
 * step adds variance it does not see (Bonnabel et al., "On the covariance
 * of ICP-based scan-matching techniques", 2016). Measured on the simulated
 * scenes (featloc-bench with covariance_inflation = 1), the median NEES is
 * 1.4-1.8 times the consistent 2.37 (lab 1.4, office, hall 1.6-1.8), and
 * the spread of the estimate 0.6-0.8 times Censi's variance when the true
 * correspondences are held fixed. Since the local lines' direction errors
 * are taken out of H (PointToLineCovariance), and the residuals' own
 * scatter bounds Censi's (covariance_residual_span), the default 1.15 makes
 * the office's unit-test route and the simulated office and lab consistent
 * (doc/cfidc-matcher.md; 1.2 before the residual span).
 *
 * Failure: fewer than min_pairs closest-point pairs, no convergence, or
 * the pairs leave a direction unconstrained (singular or beyond
 * max_translation_sigma / max_rotation_sigma; the reason names the
 * direction). guess_gate_chi2 is for the matchers built on this class
 * (ScanMatcher::guessGateChi2): an estimate implausibly far from the
 * initial guess (Mahalanobis^2 in the robot frame above it) is a wrong
 * local minimum, such as the next door along a corridor. */
class IterativeDualCorrespondence
{
   public:
	struct Parameters : public mrpt::config::CLoadableOptions
	{
		unsigned int max_iterations = 500;
		double error_ratio = 1e-6;
		double window_sigmas = 3;  //!< B_0, D_0 in standard deviations of the guess
		double min_bearing_window = mrpt::DEG2RAD(0.5);	 //!< [rad] B_min
		double min_pair_distance = 0.1;	 //!< [m] D_min
		double max_pair_distance = 2.0;	 //!< [m] cap of D_0
		unsigned int window_iterations = 5;	 //!< B_k, D_k reach their minima here
		unsigned int dual_decimation = 2;  //!< point_to_line: every N-th point in the dual phase
		unsigned int min_pairs = 10;
		std::string final_phase = "point_to_line";	//!< point_to_line | idc
		double step_tolerance = 0.25;  //!< point_to_line convergence [sigmas]
		/** point_to_line: a reference edge's local line grows over up to
		 * this many neighbours on each side (ReferencePolyline::build). */
		unsigned int line_half_window = 6;
		/** point_to_line: a current point is paired with a local line only
		 * if the line's direction is known this well
		 * (ReferencePolyline::directionSigma) [rad]. */
		double max_line_direction_sigma = mrpt::DEG2RAD(5.0);
		/** point_to_line: a local line in a segment of at least
		 * face_segment_extent pairs if its direction is known to this
		 * [rad], instead of max_line_direction_sigma: the short faces of a
		 * large structure (a door recess's jambs, a step, a pillar's side),
		 * whose lines cannot grow past their corners to
		 * max_line_direction_sigma but are the surface, and which alone
		 * fix the motion along a curved corridor (doc/benchmarks.md,
		 * "Issue 15, thirty-first session"). Small
		 * isolated things (a leg, a trunk) keep the stricter gate: they
		 * move or are round. 0 = off (max_line_direction_sigma for all, as
		 * until 2026-12-03). */
		double max_face_direction_sigma = mrpt::DEG2RAD(8.0);
		double face_segment_extent = 1.0;  //!< [m] see max_face_direction_sigma
		/** The direction sigma [rad] a local line on a segment of this
		 * extent [m] (ReferencePolyline::segmentExtent) must not exceed to
		 * pair: max_face_direction_sigma on a large structure's segment,
		 * else max_line_direction_sigma. */
		double lineDirectionGate(double segmentExtent) const
		{
			return max_face_direction_sigma > max_line_direction_sigma &&
					segmentExtent >= face_segment_extent
				? max_face_direction_sigma
				: max_line_direction_sigma;
		}
		/** point_to_line: a local line whose direction is still known worse
		 * than max_line_direction_sigma after line_half_window neighbours a
		 * side grows on until it is not (up to
		 * ReferencePolyline::kLongestLineFactor times as many), instead of
		 * being left out: dense, noisy scans. */
		bool grow_lines_to_direction_sigma = true;
		/** point_to_line: a local line whose points bow away from it by
		 * more than this many standard errors of the quadratic term keeps
		 * the bow, a local parabola (ReferencePolyline::build's
		 * bowSigmas): on a curved wall a chord biases the heading; 0 = off
		 * (straight lines only, as until 2026-12-03). */
		double line_bow_sigmas = 3.0;
		/** point_to_line, with line_bow_sigmas: a segment whose lines, one
		 * window apart, bow one way (their median t beyond
		 * line_bow_sigmas) keeps every line's bow (ReferencePolyline::build's
		 * bowPerSegment): on a round wall each bow alone stays under the
		 * threshold, yet their chords bias the motion together. Off by
		 * default: it helps the rotunda's and the ring's pairs, but the
		 * rotunda's whole matcher-chain runs went from 68 to 1052 mm ATE
		 * (doc/benchmarks.md, "Issue 15, thirty-third session"). */
		bool line_bow_per_segment = false;
		/** point_to_line: a segment shorter than face_segment_extent whose
		 * points a circle fits better than a line by more than this many
		 * sigmas of their noise (and within it) is a small round thing (a
		 * trunk, a pole, a leg): its points' residual is their distance
		 * from the circle (ReferencePolyline::build's circleSigmas), and
		 * they pair whatever their local lines' direction sigma. A
		 * trunk's four to eight points give lines known to 8 deg or
		 * worse, which max_line_direction_sigma left unpaired (the
		 * orchard: doc/benchmarks.md, "Issue 15, thirty-second
		 * session"). 0 = off (lines only, as until 2026-12-04). */
		double circle_fit_sigmas = 3.0;
		/** The target ReferencePolyline::build grows local lines to [rad]. */
		double lineTargetDirectionSigma() const
		{
			return grow_lines_to_direction_sigma ? max_line_direction_sigma : 0.0;
		}
		double guess_gate_chi2 = 21.1;	//!< 99.99% for 3 dof; 0 = off
		double covariance_inflation = 1.15;  //!< variance scale of the covariance (1.2 until the residual span)
		double min_range_sigma = 0.005;	 //!< [m] covariance noise floor
		/** [m] covariance: the residuals' own gradient scatter, with the
		 * pairs within this arc of each other counted together, bounds
		 * Censi's from below (PointToLineCovariance::compute's
		 * residualSpan; 0 = off, Censi's alone, as until 2026-12-04).
		 * 0.5 m, about a local line's reach at a few metres, lies between
		 * the 0.3 and 1 m first tried (alike on the office and three
		 * held-out scenes); covariance_inflation was then set again on the
		 * calibration scenes alone (doc/benchmarks.md, "Issue 15,
		 * thirty-third session"). */
		double covariance_residual_span = 0.5;
		double max_translation_sigma = 0.1;	 //!< [m]
		double max_rotation_sigma = mrpt::DEG2RAD(3.0);	 //!< [rad]

		void loadFromConfigFile(
			const mrpt::config::CConfigFileBase& c,
			const std::string& s) override;
		void saveToConfigFile(
			mrpt::config::CConfigFileBase& c,
			const std::string& s) const override;
	};

	struct Result
	{
		bool success = false;
		std::string failureReason;
		mrpt::math::TPose2D estimate;
		Eigen::Matrix3d cov = Eigen::Matrix3d::Identity();
		unsigned int iterations = 0;
		size_t pairs = 0;  //!< closest-point pairs at the end
		double rangeSigma = 0;	//!< noise estimated for the covariance [m]
		/** On a failure because the pairs leave one direction
		 * unconstrained while they fix the other two (a corridor): that
		 * direction (unit, x y yaw; the largest of `cov`), for
		 * ScanMatcher's free_direction_from_guess. Zero otherwise. */
		Eigen::Vector3d freeDirection = Eigen::Vector3d::Zero();
	};

	IterativeDualCorrespondence() = default;
	explicit IterativeDualCorrespondence(const Parameters& p) : params(p) {}

	/** Called once, with the estimate, when the point-to-line phase starts
	 * (final_phase = point_to_line only). */
	using PhaseSwitch = std::function<void(const mrpt::math::TPose2D& x)>;
	/** Called once, with the estimate, when the point-to-line phase has
	 * converged; true if it changed the point sets (the iterations then go
	 * on from there). */
	using Revision = std::function<bool(const mrpt::math::TPose2D& x)>;

	/** Matches `current` (its own frame) against `reference` from
	 * `guess`. The two callbacks may change the objects `reference` and
	 * `current` refer to (CF-IDC re-selects its segments there); the
	 * iterations and the covariance then use the new sets. */
	void run(
		const ReferencePolyline& reference, const std::vector<ScanPoint>& current,
		const mrpt::poses::CPosePDFGaussian& guess, Result& result,
		const PhaseSwitch& onPointToLine = {}, const Revision& onConverged = {});

	/** Median distance from each point of `current`, moved by x, to the
	 * reference polyline (searched within `maxDistance`; points farther
	 * count as maxDistance). */
	static double medianDistance(
		const ReferencePolyline& reference, const ScanPoint* current, size_t n,
		const mrpt::math::TPose2D& x, double maxDistance);

	Parameters params;
	/** [m] Round things this close (centre to centre) are tested as one
	 * (dropMovedRoundThing): a person's legs stand 0.1-0.4 m apart. */
	static constexpr double kRoundGroupDistance = 1.0;
	/** A group of round things may carry at most this many times the
	 * information of all the other pairs along any direction of the
	 * motion (dropMovedRoundThing): with 4 the others alone know each
	 * direction to at most sqrt(5) = 2.2 times the sigma of all together,
	 * enough for a moved group to show in their residuals. (1 and 2 cost
	 * the orchard 0.6-0.9 points of flagged pairs, where two near trunks
	 * share the motion along the rows; 1-4 give the corridor with people
	 * the same figures: doc/benchmarks.md, "Issue 15, thirty-second
	 * session".) */
	static constexpr double kRoundShareOfInformation = 4.0;
	/** [m] The range lattice's cell q / sqrt(12) of the scans matched (0:
	 * none; set by the matcher per match): it floors the range noise of
	 * the readings put back on their surfaces, whose errors are shared
	 * along each run; readings kept on their level carry theirs as a
	 * shared error group (ScanPoint::sharedErrorGroup) instead. */
	double rangeLatticeCellSigma = 0;

   private:
	/** One Gauss-Newton step on the point-to-line error of `pairs`
	 * (closest-point pairs made at x); false when it
	 * cannot be taken. `stepSigmas`: the step's length in standard
	 * deviations of the estimate. */
	static bool pointToLineStep(const ReferencePolyline& reference,
		const std::vector<ScanPoint>& current, const std::vector<PointToLinePair>& pairs,
		mrpt::math::TPose2D& x, double& stepSigmas);
	/** The point-to-line phase's pair for current point i at (qx, qy) in
	 * the reference frame, whose closest point is `hit`: with the circle
	 * of the round thing it lies on (unless skipRound marks it), else with
	 * its edge's local line if that passes the gates; false for none.
	 * `distance`: the point's from that surface. */
	bool pointToLinePair(const ReferencePolyline& reference, const ReferencePolyline::Hit& hit,
		uint32_t i, double qx, double qy, const std::vector<char>& skipRound, PointToLinePair& pair,
		double& distance) const;

	/** At the point-to-line phase's convergence, the round things
	 * (ReferencePolyline::circle) that may have moved are dropped: a
	 * walking person's legs are round things too. Things whose centres lie
	 * within kRoundGroupDistance of each other are one group (legs, people
	 * side by side). A group without which some direction of the motion
	 * is unconstrained (its information within
	 * PointToLineCovariance::kInventedMargin of what noisy normals
	 * invent), or that carries more than kRoundShareOfInformation times the
	 * others' information along one, cannot be told from a static one and
	 * goes first; else the group
	 * whose current points least agree with the estimate the other pairs
	 * give (chi^2 of their residuals there, against the points' noise,
	 * their circles' fits and that estimate's covariance, above the 99.9%
	 * quantile). One group per call, marked in m_roundDropped: true if one
	 * was (the iterations then go on without it). */
	bool dropMovedRoundThing(const ReferencePolyline& reference,
		const std::vector<ScanPoint>& current, const mrpt::math::TPose2D& x, double D);
	/** dropMovedRoundThing's test of one group (the pairs
	 * m_looOrder[first, end), of group `group` in m_looGroup): the
	 * point-to-line phase from x without it, pairs within D, for up to
	 * kLeftOutIterations steps; the chi^2 of its points' residuals there
	 * over its 99.9% quantile (infinity when the others leave a direction
	 * unconstrained). */
	double leftOutGroupRatio(const ReferencePolyline& reference,
		const std::vector<ScanPoint>& current, const mrpt::math::TPose2D& x, double D, size_t first,
		size_t end, int32_t group);
	static constexpr unsigned int kLeftOutIterations = 10;

	std::vector<PointToLinePair> m_lines;  // reused buffers
	std::vector<char> m_roundDropped;  //!< per circle of the reference
	std::vector<Eigen::Vector3d> m_looGradients;
	std::vector<Eigen::Matrix3d> m_looInvented;
	std::vector<int32_t> m_looGroup;  //!< per round thing, its group's label
	std::vector<char> m_looSkip;
	std::vector<PointToLinePair> m_looPairs;
	std::vector<std::pair<int32_t, uint32_t>> m_looOrder;  //!< (circle, pair)
	std::vector<double> m_lineDistances, m_scratch;
	std::vector<Eigen::Vector4d> m_cp, m_mrp;  // (q, matched point)
	std::vector<double> m_ranges;
	/** Per current point, the last answers of the two searches. */
	std::vector<uint32_t> m_closestHint, m_rangeHint;
};
}  // namespace featloc
