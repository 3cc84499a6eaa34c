#pragma once
#include <optional>

#include "featloc/ekf/EkfLocalizer.h"
#include "featloc/estimators/PoseEstimator.h"

namespace featloc
{
/** `[Pipeline] estimator = ekf`: the EKF front end (EkfLocalizer) fed by
 * the pipeline. Each step: predict with the odometry increment, fuse the
 * scan matcher's motion from the keyframe scan (when it succeeded and
 * passes the gate; otherwise the prediction stands and
 * lastFallbackReason() says why), then the step's landmark observations;
 * a new keyframe re-clones the pose. The matcher's covariance is scaled by
 * [Ekf] matcher_covariance_scale first. */
class EkfEstimator : public PoseEstimator
{
   public:
	explicit EkfEstimator(const EkfOptions& options) : m_filter(options) {}

	std::string name() const override { return "ekf"; }
	bool usesScanMatcher() const override { return true; }
	void initialize(const mrpt::poses::CPosePDFGaussian& initialPose) override;
	bool process(const EstimationStep& step, const MatchResult* match) override;
	void markKeyframe() override;
	std::optional<mrpt::poses::CPose2D> currentKeyframePose() const override
	{
		return m_filter.keyframePose().mean;
	}
	const mrpt::poses::CPosePDFGaussian& pose() const override { return m_pose; }
	bool keepsLandmarks() const override { return true; }
	std::vector<EstimatedLandmark> landmarks() const override { return m_filter.landmarks(); }
	std::string lastFallbackReason() const override { return m_reason; }

	const EkfLocalizer& filter() const { return m_filter; }

   private:
	/** Odometry and landmarks since the keyframe, matches of earlier
	 * keyframe intervals. */
	EkfLocalizer m_filter;
	/** m_filter plus the latest accepted match from the keyframe, carried
	 * forward; it becomes m_filter at the next keyframe. */
	std::optional<EkfLocalizer> m_withMatch;
	mrpt::poses::CPosePDFGaussian m_pose;
	std::string m_reason;
};
}  // namespace featloc
