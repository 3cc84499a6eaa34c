#pragma once
#include <opencv2/core/mat.hpp>

namespace featloc
{
/** A stereo pair's images, decoded once by StereoImagesHandler when it
 * checks them: grey CV_8U, equal sizes, matching the calibration. Kept out
 * of EstimationStep.h (which only forward-declares it) so that OpenCV's
 * headers stay out of the widely included ones. */
struct DecodedStereoPair
{
	cv::Mat left, right;
};
}  // namespace featloc
