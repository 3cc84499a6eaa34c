#pragma once
#include <opencv2/core/mat.hpp>

#include "featloc/stereo/StereoLandmarkFrame.h"

namespace featloc
{
/** The left image of one stereo pair with what the landmark extractor
 * made of it, as the paper's Figs. 5-6 show it:
 * - each reference plane's disparity pixels (2.3) tinted, one colour per plane;
 * - its boundary (3.2) as a long vertical line with its 3-sigma extent
 *   as short horizontal bars at the top and the bottom;
 * - vertical segments: detected (2.1) thin grey, matched but rejected
 *   (2.2 / 2.4) orange, on a plane but not selected (4) yellow,
 *   selected landmarks thick green with their index.
 * A legend row at the bottom says which is which. */
class StereoDebugPicture
{
   public:
	/** A BGR picture of `left` (CV_8U grey or BGR) with `frame` drawn on it. */
	static cv::Mat draw(const cv::Mat& left, const StereoLandmarkFrame& frame);
};
}  // namespace featloc
