#pragma once
#include <mrpt/math/CMatrixFixed.h>
#include <mrpt/math/TPose2D.h>

#include <string>
#include <vector>

namespace featloc
{
/** matches.txt: one row per scan match of a run (MatchTableWriter writes
 * it, featloc-viewer reads it), so the matcher's part of every step can be
 * looked at and re-run later:
 *
 *   t ref_t status used iterations time_ms goodness ref_points cur_points
 *   guess_x guess_y guess_yaw est_x est_y est_yaw
 *   c_xx c_xy c_xyaw c_yy c_yyaw c_yawyaw  g_xx ... g_yawyaw  a_xx ... a_yawyaw
 *   reason...
 *
 * t: the current scan's time, ref_t: its reference (keyframe) scan's;
 * status: ok | overruled (a success whose guess-gate rejection the scans
 * overruled, ScanMatcher::arbitrateGuessGate) | failed | gate (converged,
 * rejected by the guess gate);
 * used: 1 if the estimator used it; poses are robot-frame motions from the
 * reference scan (m, rad), c_ the estimate's covariance, g_ the guess's,
 * a_ the gate allowance added to the guess's (ScanMatcher::match); reason: the
 * failure, the overruled gate's and the evidence, a fallback matcher's
 * success and why the configured matcher gave up, a flagged success's
 * ambiguity ("ambiguous: ..."), or the estimator's gate reason ("not used:
 * ..."), to the end of the line ('-': none). */
class MatchTableFile
{
   public:
	struct Row
	{
		double t = 0, referenceT = 0;  //!< [s]
		/** "ok", "failed", "gate" (the guess gate rejected it) or "overruled"
		 * (a success whose guess-gate rejection the scans overruled). */
		std::string status;
		bool used = false;
		unsigned iterations = 0;
		double timeMs = 0, goodness = 0;
		unsigned referencePoints = 0, currentPoints = 0;
		mrpt::math::TPose2D guess, estimate;
		mrpt::math::CMatrixDouble33 cov, guessCov, gateAllowance;
		std::string reason;	 //!< empty: none
	};
	static const char* header();
	/** Throws InputError naming the file and line of a malformed row. */
	static std::vector<Row> read(const std::string& path);
};
}  // namespace featloc
