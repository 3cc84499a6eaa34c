#include "featloc/estimators/PoseEstimator.h"

#include "featloc/core/ConfigError.h"

namespace featloc
{
IMPLEMENTS_VIRTUAL_MRPT_OBJECT(PoseEstimator, mrpt::rtti::CObject, featloc)

void PoseEstimator::start(
	const mrpt::poses::CPosePDFGaussian& initialPose, const EstimationStep& first)
{
	initialize(initialPose);
	if (!first.landmarks.empty() || first.stereoImages) process(first, nullptr);
}

void PoseEstimator::setStereoLandmarks(std::shared_ptr<StereoLandmarkExtractor>)
{
	throw ConfigError(
		"[StereoLandmarks] class is set but estimator '" + name() +
		"' keeps no landmarks: use [Pipeline] estimator = ekf");
}
}  // namespace featloc
