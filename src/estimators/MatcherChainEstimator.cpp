#include "featloc/estimators/MatcherChainEstimator.h"

namespace featloc
{
IMPLEMENTS_MRPT_OBJECT(MatcherChainEstimator, PoseEstimator, featloc)

void MatcherChainEstimator::initialize(
	const mrpt::poses::CPosePDFGaussian& initialPose)
{
	m_pose = initialPose;
	m_keyframePose = initialPose;
}

bool MatcherChainEstimator::process(
	const EstimationStep& step, const MatchResult* match)
{
	const bool useMatch = match && match->success;
	if (useMatch)
	{
		m_pose = m_keyframePose;
		m_pose += match->estimate;
	}
	else
	{
		m_pose += step.odometry;
	}
	return useMatch;
}
}  // namespace featloc
