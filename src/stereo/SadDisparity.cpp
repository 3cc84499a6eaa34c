#include "featloc/stereo/SadDisparity.h"

#include <opencv2/calib3d.hpp>

#include <algorithm>
#include <vector>

#include "featloc/stereo/SegmentBand.h"

namespace featloc
{
cv::Mat SadDisparity::compute(const cv::Mat& left, const cv::Mat& right, int minDisparity, int numDisparities) const
{
	// OpenCV's block matcher needs the window smaller than the image (it throws
	// otherwise): an image no larger than the window has no area-based
	// disparity at all (fuzz/regressions/stereo), so
	// every segment match goes unsupported ("no SAD disparity around it").
	if (left.cols <= options.block_size || left.rows <= options.block_size)
		return cv::Mat(left.rows, left.cols, CV_32F, cv::Scalar(-1));
	// Eq. (2): SAD in both directions, kept where they agree within 1 px.
	auto bm = cv::StereoBM::create(numDisparities, options.block_size);
	bm->setMinDisparity(minDisparity);
	bm->setDisp12MaxDiff(1);
	bm->setUniquenessRatio(options.uniqueness_ratio);
	bm->setTextureThreshold(options.texture_threshold);
	cv::Mat d16, d;
	bm->compute(left, right, d16);
	d16.convertTo(d, CV_32F, 1.0 / 16);
	// StereoBM marks a pixel it rejects with minDisparity - 1: a positive,
	// plausible disparity as soon as the search starts above 1 px (each
	// frame searches only the walls' range). Every reader takes <= 0 for
	// invalid, so they are set to -1 (they had passed for the farthest
	// surface: a wall's end hidden by a nearer corner was "seen" against
	// them, and landmarks placed from it put the robot 15-30 cm off).
	d.setTo(-1, d16 < minDisparity * 16);
	return d;
}

std::string SadDisparity::support(const cv::Mat& disparity, const VerticalSegment& l, const SegmentMatch& m) const
{
	std::vector<float> d;
	size_t band = 0;
	forSegmentBand(l, m, disparity.cols, disparity.rows, 3, [&](int u, int v) {
		band++;
		const float x = disparity.at<float>(v, u);
		if (x > 0) d.push_back(x);
	});
	if (d.size() < std::max<size_t>(3, band * 3 / 10)) return "no SAD disparity around it";
	std::nth_element(d.begin(), d.begin() + static_cast<long>(d.size() / 2), d.end());
	const double med = d[d.size() / 2];
	if (std::abs(med - m.disparity) > options.tolerance_px)
		return "disparity " + std::to_string(m.disparity).substr(0, 5) + " px, SAD image " +
			   std::to_string(med).substr(0, 5) + " px";
	return "";
}
}  // namespace featloc
