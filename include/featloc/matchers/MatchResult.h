#pragma once
#include <mrpt/core/Clock.h>
#include <mrpt/math/CVectorFixed.h>
#include <mrpt/poses/CPosePDFGaussian.h>

#include <cstddef>
#include <string>

namespace featloc
{
/** Outcome of one scan-to-scan match.
 *
 * `estimate` is the pose of the current scan's robot frame in the reference
 * scan's robot frame (the motion from reference to current), with its 3x3
 * covariance (x [m], y [m], yaw [rad]). When `success` is false the estimate
 * is whatever the matcher ended with and must not be used; `failureReason`
 * says why (too few points, no convergence, unconstrained direction...). */
struct MatchResult
{
	bool success = false;
	std::string failureReason;
	mrpt::poses::CPosePDFGaussian estimate;
	/** The matcher converged, but its estimate was too far from the initial
	 * guess for the guess's covariance (guess_gate_chi2): `estimate` is the
	 * converged motion. */
	bool rejectedByGuessGate = false;
	/** Non-empty on a success that the guess gate had rejected and the
	 * scans overruled (ScanMatcher::arbitrateGuessGate): the gate's reason
	 * and the evidence against the guess. */
	std::string guessGateOverruled;
	/** What kind of failure (empty on success; set on every failure that
	 * ScanMatcher::match returns), for the counts of
	 * summary.json and featloc-bench: "too_few_points", "no_overlap" (the
	 * coarse search), "left_window" (the iterations converged outside the
	 * window the coarse search scored, to an estimate not clearly better than
	 * a solution inside it), "ambiguous" (another solution explains the scan about
	 * as well as the estimate), "guess_gate", "non_finite" (the matcher
	 * reported success with a NaN or infinite estimate or covariance), or
	 * "matcher" (the matcher's own reasons). */
	std::string failureKind;
	/** A success that the coarse search found ambiguous (coarse_on_ambiguity
	 * = inflate): the estimate's covariance was grown to cover every
	 * solution the points do not reject (ambiguityReason says the first),
	 * so a filter keeps its prediction along the ambiguity and uses the
	 * match across it. Counted as flagged, not as a silent error. */
	bool ambiguous = false;
	std::string ambiguityReason;
	/** Set by the matcher on a failure whose only cause is one direction
	 * its points leave free while they fix the other two (a corridor): that
	 * direction (unit; x, y, yaw). ScanMatcher's free_direction_from_guess
	 * then keeps the guess along it and makes the result a flagged success
	 * (`ambiguous`, `guessKeptAlongFreeDirection`); in the robot frame once
	 * ScanMatcher::match returns. Zero otherwise. */
	mrpt::math::CVectorFixedDouble<3> freeDirection;
	/** The estimate along `freeDirection` is the guess's (fused with the
	 * little the points say along it), across it the matcher's, and the
	 * covariance along it the guess's: a filter whose prediction is that
	 * guess keeps its prediction there (EkfEstimator). */
	bool guessKeptAlongFreeDirection = false;
	/** Non-empty when the matcher took its own fallback and why (CF-IDC:
	 * the curvature pairing kept under a third of the points, so IDC
	 * started from every segment). Counted by summary.json and
	 * featloc-bench. */
	std::string matcherFallback;
	/** Segments of the current scan the matcher dropped as moved because
	 * their residuals at the estimate said so (CF-IDC's
	 * segment_residual_chi2); 0 for the other matchers. */
	size_t segmentsDroppedByResiduals = 0;
	/** Non-empty when the configured matcher failed and its fallback
	 * (`fallback_class`) made this result: "<class>: <why it failed>", or
	 * when its match was ambiguous and the fallback's was not
	 * (`fallback_on_ambiguity`): "<class>: ambiguous, <why>", or when its
	 * covariance was wide (`fallback_above_sigma_xy`): "<class>: weak, ...".
	 * Everything else in the result is the fallback's. Counted by
	 * summary.json and featloc-bench. */
	std::string primaryFailure;
	/** The share of points on the reference at the coarse search's best
	 * pose (CorrelativeScanSearch; 0 when it did not run). */
	double coarseScore = 0;
	/** The step [m] of the range lattice the current scan's readings sat
	 * on (RangeLattice; 0: none, or not looked for), and whether the
	 * matcher put them back on their surfaces (dequantize_ranges). */
	double rangeLatticeStep = 0;
	bool rangesDequantized = false;
	/** The coarse search was on but skipped: the iterations from the guess
	 * succeeded at a pose that puts this share of the current points near
	 * the reference (coarse_confirm_share; 0 otherwise). */
	double confirmedShare = 0;
	/** The share confirmed the iterations from the guess, but a pose slid
	 * along the estimate's least certain direction fit as well
	 * (coarse_confirm_probe), so the coarse search ran. */
	bool confirmationSlid = false;
	/** What the gates add to the guess's covariance (ScanMatcher::match's
	 * gateAllowance; zero when none). */
	mrpt::math::CMatrixDouble33 gateAllowance;
	/** The initial guess the match started from (robot frame, as given to
	 * ScanMatcher::match), kept for the outputs and the viewer. */
	mrpt::poses::CPosePDFGaussian guess;
	/** Timestamp of the reference scan (zero for point-set matches). */
	mrpt::Clock::time_point referenceTime{};
	unsigned int iterations = 0;
	double timeSeconds = 0;	 //!< wall time of the match, conversions included
	/** Fraction of current-scan points paired with the reference at the end,
	 * in [0, 1] (matcher-specific; 0 if not computed). */
	double goodness = 0;
	size_t referencePoints = 0;	 //!< valid points used from the reference
	size_t currentPoints = 0;  //!< valid points used from the current scan
};

}  // namespace featloc
