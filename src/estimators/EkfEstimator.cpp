#include "featloc/estimators/EkfEstimator.h"

namespace featloc
{
IMPLEMENTS_MRPT_OBJECT(EkfEstimator, PoseEstimator, featloc)

void EkfEstimator::loadParams(const mrpt::config::CConfigFileBase& cfg)
{
	m_filter.options.loadFromConfigFile(cfg, paramsSection());
}

void EkfEstimator::saveParams(mrpt::config::CConfigFileBase& cfg) const
{
	m_filter.options.saveToConfigFile(cfg, paramsSection());
}

void EkfEstimator::initialize(const mrpt::poses::CPosePDFGaussian& initialPose)
{
	m_filter.reset(initialPose);
	m_pose = m_filter.robotPose();
	m_reason.clear();
}

bool EkfEstimator::process(const EstimationStep& step, const MatchResult* match)
{
	m_filter.predict(step.odometry);
	m_reason.clear();
	bool used = false;
	if (match && match->success)
	{
		mrpt::poses::CPosePDFGaussian z = match->estimate;
		z.cov *= m_filter.options.matcher_covariance_scale;
		// Gated against the state without this keyframe's earlier matches:
		// they measured (nearly) the same thing, with (nearly) the same
		// error, so only the latest accepted one is held for fusion.
		const auto u = m_filter.testRelativeMotion(z);
		used = u.used;
		m_reason = u.reason;
		if (used) m_filter.holdRelativeMotion(z);
	}
	else if (match)
		m_reason = "the match failed: " + match->failureReason;
	if (!step.landmarks.empty()) m_filter.updateLandmarks(step.landmarks);
	m_pose = m_filter.robotPose();
	return used;
}

void EkfEstimator::markKeyframe()
{
	m_filter.cloneKeyframe();  // fuses the held match of the ending interval
	m_pose = m_filter.robotPose();
}
}  // namespace featloc
