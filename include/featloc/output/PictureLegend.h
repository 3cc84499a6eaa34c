#pragma once
#include <opencv2/core/mat.hpp>

#include <string>
#include <utility>
#include <vector>

namespace featloc
{
/** A legend row along the bottom of a picture: a black band with a
 * coloured stroke and a label per item. */
class PictureLegend
{
   public:
	static void draw(cv::Mat& bgr, const std::vector<std::pair<std::string, cv::Scalar>>& items);
};
}  // namespace featloc
