#pragma once
#include "featloc/ekf/EkfLocalizer.h"
#include "featloc/stereo/StereoLandmarkFrame.h"

namespace featloc
{
/** What one step's stereo pair gave the estimator: the extractor's stages
 * (sections 2-4) and what the EKF did with the observations (section 5). */
struct StereoStepResult
{
	StereoLandmarkFrame frame;
	EkfLocalizer::VerticalUpdate update;
	std::string map;  //!< the extractor's map file
};
}  // namespace featloc
