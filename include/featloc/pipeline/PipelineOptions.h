#pragma once
#include <mrpt/poses/CPosePDFGaussian.h>
#include <mrpt/config/CLoadableOptions.h>

#include <cmath>
#include <string>
#include <vector>

namespace featloc
{
/** `[Pipeline]`: which estimator turns odometry and matches into poses. */
struct PipelineOptions : public mrpt::config::CLoadableOptions
{
	static constexpr const char* kSection = "Pipeline";

	/** "odometry" (dead reckoning), "matcher" (chained scan matches with
	 * odometry as prior and fallback) or "ekf" (EkfEstimator). */
	std::string estimator = "matcher";
	/** Robot pose at the first scan: x [m], y [m], yaw [rad] in memory
	 * (degrees in the file). */
	std::vector<double> initial_pose = {0, 0, 0};
	/** `initial_pose = global`: the pose is unknown and is found in the
	 * [Localization] map (MapLocalizer's global search); until then the
	 * estimate starts at the origin with a covariance that says so. */
	bool global_start = false;
	/** Standard deviations of initial_pose: x [m], y [m], yaw [rad] in
	 * memory (degrees in the file). Zero: the run's origin, exact (motion
	 * relative to the start); in a known map ([Localization] map), how well
	 * the start in the map is known, so the first map matches can correct
	 * it. */
	std::vector<double> initial_pose_sigma = {0, 0, 0};
	/** initial_pose with the covariance of initial_pose_sigma (global
	 * start: the origin, sigma kUnknownSigmaXY and pi). */
	mrpt::poses::CPosePDFGaussian initialPose() const;
	/** The scan matcher matches each scan against a reference (keyframe)
	 * scan, replaced when the estimated motion since it reaches
	 * keyframe_distance [m] or keyframe_angle [rad] (or when a match fails,
	 * with failed_match_keeps_keyframe false).
	 * Both 0: every scan is the next one's reference (scan-to-previous-scan).
	 * Larger values stop small per-scan errors from accumulating on
	 * high-rate, noisy logs (as icp-slam's localizationLinDistance): 1 m /
	 * 20 deg is what works on MRPT's logs and featloc's scenes (ATE 0.21 m vs
	 * 7.2 m with every scan a keyframe on MRPT's simul.rawlog,
	 * doc/benchmarks.md), so it is the default. */
	double keyframe_distance = 1.0;
	static constexpr double kUnknownSigmaXY = 1000.0;  //!< [m]
	double keyframe_angle = 20.0 * M_PI / 180.0;
	/** A failed match keeps the reference scan, which is replaced only when
	 * the estimate's motion since it reaches keyframe_distance or
	 * keyframe_angle: the next good match against it then measures the
	 * failed steps too, and corrects their odometry. false: a failed
	 * match makes its scan the reference, and the odometry error of that
	 * step stays in the estimate (doc/benchmarks.md, "Issue 15, eleventh
	 * session"). Ignored with every scan a keyframe. */
	bool failed_match_keeps_keyframe = true;
	/** With failed_match_keeps_keyframe: after a failed match the
	 * reference is replaced only when the estimate's motion since it
	 * reaches this many times keyframe_distance or keyframe_angle. At 1 a
	 * failed scan in a turn (15 deg a scan) that reaches keyframe_angle
	 * became the reference with its step's odometry error, although the
	 * next scan's match, one step further, would measure that step; the
	 * factor bounds how far behind the reference falls in a streak of
	 * failures (doc/benchmarks.md, "Issue 15, twenty-first session"). */
	double failed_match_keyframe_factor = 2.0;

	void loadFromConfigFile(
		const mrpt::config::CConfigFileBase& c,
		const std::string& s) override;
	void saveToConfigFile(
		mrpt::config::CConfigFileBase& c, const std::string& s) const override;
};
}  // namespace featloc
