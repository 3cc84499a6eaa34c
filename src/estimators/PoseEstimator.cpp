#include "featloc/estimators/PoseEstimator.h"

namespace featloc
{
IMPLEMENTS_VIRTUAL_MRPT_OBJECT(PoseEstimator, mrpt::rtti::CObject, featloc)

void PoseEstimator::start(
	const mrpt::poses::CPosePDFGaussian& initialPose, const EstimationStep& first)
{
	initialize(initialPose);
	if (!first.landmarks.empty()) process(first, nullptr);
}
}  // namespace featloc
