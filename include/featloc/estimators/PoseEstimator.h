#pragma once
#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/poses/CPosePDFGaussian.h>
#include <mrpt/rtti/CObject.h>

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "featloc/ekf/EstimatedLandmark.h"
#include "featloc/matchers/MatchResult.h"
#include "featloc/estimators/EstimationStep.h"

namespace featloc
{
class StereoLandmarkExtractor;
struct StereoStepResult;

/** Turns the per-step inputs (odometry motion, scan-matcher result,
 * landmark observations) into the robot's global pose with covariance.
 *
 * Estimators are MRPT RTTI classes like the scan matchers, created by name
 * through the class registry (`[Pipeline] estimator = featloc::EkfEstimator`,
 * or the short aliases odometry | matcher | ekf; see PoseEstimatorFactory),
 * each reading its parameters from its own section. One instance per run.
 * The pipeline feeds every step in order; at the first step it sets the
 * initial pose (and then processes that step's landmarks, if any). */
class PoseEstimator : public mrpt::rtti::CObject
{
	DEFINE_VIRTUAL_MRPT_OBJECT(PoseEstimator)

   public:
	~PoseEstimator() override = default;

	/** Short name shown to the user and in summary.json ("odometry",
	 * "matcher", "ekf"): the alias the configuration may use. */
	virtual std::string name() const = 0;

	/** The registered class name, e.g. "featloc::EkfEstimator". */
	std::string className() const { return GetRuntimeClass()->className; }

	/** Whether the pipeline must run the scan matcher for this estimator. */
	virtual bool usesScanMatcher() const = 0;

	/** Section of this estimator's parameters ("": it has none). */
	virtual std::string paramsSection() const { return ""; }
	/** Reads paramsSection(); unspecified keys keep their defaults. Throws
	 * ConfigError on a bad value. */
	virtual void loadParams(const mrpt::config::CConfigFileBase&) {}
	/** Writes every parameter with its unit and meaning as a comment. */
	virtual void saveParams(mrpt::config::CConfigFileBase&) const {}

	/** Pose at the first step. */
	virtual void initialize(const mrpt::poses::CPosePDFGaussian& initialPose) = 0;

	/** The first step: initialize() at `initialPose`, then what that step
	 * saw (landmarks) is fused there. */
	void start(const mrpt::poses::CPosePDFGaussian& initialPose, const EstimationStep& first);

	/** Advances to the step's time. `match` is the scan matcher's motion
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

	/** Stereo landmarks: the extractor that turns each step's stereo pair
	 * into landmark observations. Estimators that keep no landmarks throw
	 * ConfigError (the default). */
	virtual void setStereoLandmarks(std::shared_ptr<StereoLandmarkExtractor> extractor);
	/** What the last process() made of its step's stereo pair, or null
	 * (no pair, or no extractor). */
	virtual const StereoStepResult* lastStereo() const { return nullptr; }

	/** Whether the estimator can fuse absolute poses (localization in a
	 * known map, [Localization] map). */
	virtual bool fusesAbsolutePoses() const { return false; }
	/** After process(): fuses `z`, the robot's pose now in the map frame
	 * with its covariance, unless its Mahalanobis^2 against the estimate
	 * exceeds `gateChi2`. Returns whether it was used; `reason` says why
	 * not. The default throws std::logic_error (fusesAbsolutePoses()). */
	virtual bool fuseAbsolutePose(
		const mrpt::poses::CPosePDFGaussian& z, double gateChi2, std::string& reason);

	/** The angle between the odometry's direction of travel and the
	 * scanner's that the estimator has learnt, and its sigma [rad], when it
	 * estimates one (the EKF with [Ekf] odometry_direction_sigma_DEG > 0). */
	virtual std::optional<std::pair<double, double>> odometryDirectionOffset() const { return {}; }

	/** Why the last process() did not use the match ("" if it did, or
	 * there was none). */
	virtual std::string lastFallbackReason() const { return ""; }
};
}  // namespace featloc
