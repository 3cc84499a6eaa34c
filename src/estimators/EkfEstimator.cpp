#include "featloc/estimators/EkfEstimator.h"

namespace featloc
{
void EkfEstimator::initialize(const mrpt::poses::CPosePDFGaussian& initialPose)
{
	m_filter.reset(initialPose);
	m_withMatch.reset();
	m_pose = m_filter.robotPose();
	m_reason.clear();
}

bool EkfEstimator::process(const EstimationStep& step, const MatchResult* match)
{
	m_filter.predict(step.odometry);
	if (m_withMatch) m_withMatch->predict(step.odometry);
	m_reason.clear();
	bool used = false;
	if (match && match->success)
	{
		mrpt::poses::CPosePDFGaussian z = match->estimate;
		z.cov *= m_filter.options.matcher_covariance_scale;
		// Against the filter without this keyframe's earlier matches: they
		// measured (nearly) the same thing, with (nearly) the same error.
		EkfLocalizer candidate = m_filter;
		const auto u = candidate.updateRelativeMotion(z);
		used = u.used;
		m_reason = u.reason;
		if (used) m_withMatch = std::move(candidate);
	}
	else if (match)
		m_reason = "the match failed: " + match->failureReason;
	if (!step.landmarks.empty())
	{
		m_filter.updateLandmarks(step.landmarks);
		if (m_withMatch) m_withMatch->updateLandmarks(step.landmarks);
	}
	m_pose = (m_withMatch ? *m_withMatch : m_filter).robotPose();
	return used;
}

void EkfEstimator::markKeyframe()
{
	// Commit the latest accepted match of the ending keyframe interval.
	if (m_withMatch) m_filter = std::move(*m_withMatch);
	m_withMatch.reset();
	m_filter.cloneKeyframe();
	m_pose = m_filter.robotPose();
}
}  // namespace featloc
