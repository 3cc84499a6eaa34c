#pragma once
#include <opencv2/core/mat.hpp>

#include <string>
#include <utility>
#include <vector>

#include "featloc/stereo/VerticalSegment.h"

namespace featloc
{
/** What the stereo pictures (StereoDebugPicture, StereoPairPicture) draw
 * alike: a BGR copy of an image, pixel points, vertical segments, and a
 * legend row along the bottom. */
class StereoPictureDrawing
{
   public:
	/** A BGR copy of a grey (CV_8U) or BGR image. */
	static cv::Mat toBgr(const cv::Mat& image);
	/** The pixel nearest to (u, v). */
	static cv::Point pixel(double u, double v);
	/** Segment s between rows vTop and vBottom, shifted du columns (the
	 * right image of a side-by-side pair). */
	static void segment(cv::Mat& bgr, const VerticalSegment& s, double vTop, double vBottom, double du,
		const cv::Scalar& colour, int width);
	/** A black band with a coloured stroke and a label per item. */
	static void legend(cv::Mat& bgr, const std::vector<std::pair<std::string, cv::Scalar>>& items);
};
}  // namespace featloc
