#pragma once
#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/poses/CPosePDFGaussian.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "featloc/ekf/EstimatedLandmark.h"
#include "featloc/matchers/MatchResult.h"
#include "featloc/estimators/EstimationStep.h"

namespace featloc
{
/** Turns the per-scan inputs (odometry motion, scan-matcher result) into
 * the robot's global pose with covariance. One instance per run; chosen by
 * `[Pipeline] estimator` (see PoseEstimatorFactory). The pipeline feeds every
 * step in order; for the first step it sets the initial pose instead. */
class PoseEstimator
{
   public:
	using Ptr = std::unique_ptr<PoseEstimator>;
	virtual ~PoseEstimator() = default;

	/** Name used in the configuration ("odometry", "matcher", ...). */
	virtual std::string name() const = 0;

	/** Whether the pipeline must run the scan matcher for this estimator. */
	virtual bool usesScanMatcher() const = 0;

	/** Reads the estimator's own section, if it has one. */
	virtual void loadParams(const mrpt::config::CConfigFileBase&) {}

	/** Pose at the first scan. */
	virtual void initialize(const mrpt::poses::CPosePDFGaussian& initialPose) = 0;

	/** Advances to the step's scan. `match` is the scan matcher's motion
	 * from the current reference (keyframe) scan to this one, or nullptr
	 * when no matcher ran. Returns true when the estimate used the match,
	 * false when it fell back to odometry. */
	virtual bool process(const EstimationStep& step, const MatchResult* match) = 0;

	/** The scan just processed becomes the reference of the next matches
	 * (the pipeline calls it after initialize() and after every keyframe
	 * step). */
	virtual void markKeyframe() {}

	/** The keyframe scan's pose as the estimator knows it now, when it
	 * keeps refining it (the EKF's clone); otherwise nothing, and the
	 * pipeline uses the pose estimated when the scan became the keyframe.
	 * The matcher's guess is the predicted pose seen from this pose. */
	virtual std::optional<mrpt::poses::CPose2D> currentKeyframePose() const { return {}; }

	/** Current global robot pose with covariance. */
	virtual const mrpt::poses::CPosePDFGaussian& pose() const = 0;

	/** Whether the estimator keeps point landmarks (the run then writes
	 * landmarks.txt). */
	virtual bool keepsLandmarks() const { return false; }

	/** The point landmarks the estimator keeps (none for most). */
	virtual std::vector<EstimatedLandmark> landmarks() const { return {}; }

	/** Why the last process() did not use the match ("" if it did, or
	 * there was none). */
	virtual std::string lastFallbackReason() const { return ""; }
};
}  // namespace featloc
