#include "featloc/estimators/OdometryEstimator.h"

namespace featloc
{
IMPLEMENTS_MRPT_OBJECT(OdometryEstimator, PoseEstimator, featloc)

void OdometryEstimator::initialize(
	const mrpt::poses::CPosePDFGaussian& initialPose)
{
	m_pose = initialPose;
}

bool OdometryEstimator::process(const EstimationStep& step, const MatchResult*)
{
	m_pose += step.odometry;  // x_k = x_{k-1} (+) u_k, covariance by Jacobians
	return false;
}
}  // namespace featloc
