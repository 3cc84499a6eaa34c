#include "featloc/estimators/PoseEstimator.h"

namespace featloc
{
IMPLEMENTS_VIRTUAL_MRPT_OBJECT(PoseEstimator, mrpt::rtti::CObject, featloc)
}  // namespace featloc
