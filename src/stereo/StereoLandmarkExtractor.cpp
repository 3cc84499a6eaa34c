#include "featloc/stereo/StereoLandmarkExtractor.h"

namespace featloc
{
IMPLEMENTS_VIRTUAL_MRPT_OBJECT(StereoLandmarkExtractor, mrpt::rtti::CObject, featloc)

std::string StereoLandmarkExtractor::className() const
{
	return GetRuntimeClass()->className;
}
}  // namespace featloc
