#pragma once
#include <opencv2/core/mat.hpp>

#include "featloc/stereo/StereoVerticalLines.h"

namespace featloc
{
/** Left and right images side by side with the segment stage of one pair
 * (StereoVerticalLines): detected segments thin grey; DP matches the SAD
 * disparity does not support orange, in both images; supported matches
 * green, numbered alike in both images when they gave a vertical line. A legend row at the
 * bottom. */
class StereoPairPicture
{
   public:
	static cv::Mat draw(const cv::Mat& left, const cv::Mat& right, const StereoVerticalLines::Result& r);
};
}  // namespace featloc
