#pragma once
#include <optional>

#include "featloc/ekf/EkfLocalizer.h"
#include "featloc/estimators/PoseEstimator.h"

namespace featloc
{
/** `[Pipeline] estimator = ekf`: the EKF front end (EkfLocalizer) fed by
 * the pipeline. Each step: predict with the odometry increment; hold the
 * scan matcher's motion from the keyframe scan when it succeeded and
 * passes the gate (otherwise the prediction stands and
 * lastFallbackReason() says why); update with the step's landmark
 * observations; a new keyframe fuses the held match and re-clones the
 * pose. The pose reported includes the held match. The matcher's
 * covariance is scaled by [Ekf] matcher_covariance_scale first. With a
 * stereo landmark extractor, each stereo pair is processed at the
 * predicted pose (after the point landmarks) and its vertical-line
 * observations update the same state (Moon, Miura & Shirai, section 5). */
class EkfEstimator : public PoseEstimator
{
	DEFINE_MRPT_OBJECT(EkfEstimator, featloc)

   public:
	EkfEstimator() = default;
	explicit EkfEstimator(const EkfOptions& options) : m_filter(options) {}

	std::string name() const override { return "ekf"; }
	std::string paramsSection() const override { return EkfOptions::kSection; }
	void loadParams(const mrpt::config::CConfigFileBase& cfg) override;
	void saveParams(mrpt::config::CConfigFileBase& cfg) const override;
	bool usesScanMatcher() const override { return m_filter.options.use_scan_matcher; }
	void initialize(const mrpt::poses::CPosePDFGaussian& initialPose) override;
	bool process(const EstimationStep& step, const MatchResult* match) override;
	void markKeyframe() override;
	std::optional<mrpt::poses::CPose2D> currentKeyframePose() const override
	{
		return m_filter.keyframePose().mean;
	}
	const mrpt::poses::CPosePDFGaussian& pose() const override { return m_pose; }
	bool keepsLandmarks() const override { return true; }
	std::vector<EstimatedLandmark> landmarks() const override;
	std::string lastFallbackReason() const override { return m_reason; }
	std::optional<std::pair<double, double>> odometryDirectionOffset() const override;
	bool fusesAbsolutePoses() const override { return true; }
	bool fuseAbsolutePose(
		const mrpt::poses::CPosePDFGaussian& z, double gateChi2, std::string& reason) override;
	void setStereoLandmarks(std::shared_ptr<StereoLandmarkExtractor> extractor) override
	{
		m_stereo = std::move(extractor);
	}
	const StereoStepResult* lastStereo() const override { return m_lastStereo.get(); }

	const EkfLocalizer& filter() const { return m_filter; }

   private:
	/** The one state: odometry, landmarks, the matches of earlier keyframe
	 * intervals, and the latest accepted match of this one held. */
	EkfLocalizer m_filter;
	mrpt::poses::CPosePDFGaussian m_pose;
	std::string m_reason;
	std::shared_ptr<StereoLandmarkExtractor> m_stereo;
	std::shared_ptr<StereoStepResult> m_lastStereo;
	/** Sections 2-5 on the step's stereo pair. */
	void processStereo(const EstimationStep& step);
};
}  // namespace featloc
