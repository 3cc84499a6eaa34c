#pragma once
#include <opencv2/core/mat.hpp>

#include <string>

#include "featloc/stereo/SegmentMatch.h"
#include "featloc/stereo/VerticalSegment.h"

namespace featloc
{
/** Area-based matching (Moon, Miura & Shirai 1999, section 2.2) and the
 * check it gives segment matches: OpenCV's StereoBM computes the SAD
 * disparity in both directions and keeps the pixels where the two agree
 * within 1 px (eq. 2, disp12MaxDiff); a segment match is supported when
 * the disparities in a band around its left segment have a median within
 * tolerance_px of the match's disparity. */
class SadDisparity
{
   public:
	struct Options
	{
		int block_size = 15;  //!< paper: 15x15
		int uniqueness_ratio = 5;  //!< StereoBM's, [%]
		int texture_threshold = 10;	 //!< StereoBM's
		double tolerance_px = 1.5;
	};

	SadDisparity() = default;
	explicit SadDisparity(const Options& o) : options(o) {}
	Options options;

	/** CV_32F, <= 0 where invalid; searches minDisparity ..
	 * minDisparity + numDisparities - 1 (numDisparities a multiple of 16). */
	cv::Mat compute(const cv::Mat& left, const cv::Mat& right, int minDisparity, int numDisparities) const;

	/** "" when `disparity` supports match m of left segment l, else why not. */
	std::string support(const cv::Mat& disparity, const VerticalSegment& l, const SegmentMatch& m) const;
};
}  // namespace featloc
