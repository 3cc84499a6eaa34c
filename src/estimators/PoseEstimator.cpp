#include "featloc/estimators/PoseEstimator.h"

#include <stdexcept>

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

bool PoseEstimator::fuseAbsolutePose(const mrpt::poses::CPosePDFGaussian&, double, std::string&)
{
	throw std::logic_error("estimator '" + name() + "' does not fuse absolute poses");
}
}  // namespace featloc
