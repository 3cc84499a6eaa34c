#pragma once
#include <mrpt/config/CConfigFileBase.h>
#include <opencv2/core/mat.hpp>

#include <string>
#include <vector>

#include "featloc/stereo/VerticalSegment.h"

namespace featloc
{
/** Vertical line segments from the edges of a horizontal derivative
 * (Moon, Miura & Shirai 1999, section 2.1).
 *
 * The image is smoothed (Gaussian, smoothing_sigma) and differentiated
 * horizontally (OpenCV's 3x3 Sobel, scaled to grey levels per pixel). Edge
 * pixels are the horizontal maxima of |dI/du| above min_gradient, located
 * to a fraction of a pixel by a parabola through the maximum and its two
 * neighbours. Edge pixels of one polarity in successive rows (gaps of up
 * to max_gap_rows) within max_step_px of each other are chained; a chain
 * of at least min_length_px rows whose least-squares column fit leans by
 * at most max_tilt_deg is a segment. */
class VerticalSegmentDetector
{
   public:
	struct Options
	{
		double smoothing_sigma = 1.0;  //!< [px]
		double min_gradient = 6.0;	//!< [grey levels / px]
		double min_length_px = 15;
		double max_tilt_deg = 5;
		int max_gap_rows = 2;
		double max_step_px = 1.0;

		void loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s);
		void saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const;
	};

	VerticalSegmentDetector() = default;
	explicit VerticalSegmentDetector(const Options& o) : options(o) {}
	Options options;

	/** Segments of a grey image (CV_8U or CV_32F), ordered by column. */
	std::vector<VerticalSegment> detect(const cv::Mat& grey) const;
};
}  // namespace featloc
