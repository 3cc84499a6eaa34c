#include "featloc/output/StereoPictureDrawing.h"

#include <opencv2/imgproc.hpp>

#include <cmath>

namespace featloc
{
cv::Mat StereoPictureDrawing::toBgr(const cv::Mat& m)
{
	cv::Mat out;
	if (m.channels() == 1)
		cv::cvtColor(m, out, cv::COLOR_GRAY2BGR);
	else
		out = m.clone();
	return out;
}

cv::Point StereoPictureDrawing::pixel(double u, double v)
{
	return {static_cast<int>(std::lround(u)), static_cast<int>(std::lround(v))};
}

void StereoPictureDrawing::segment(cv::Mat& img, const VerticalSegment& s, double vTop, double vBottom, double du,
	const cv::Scalar& c, int w)
{
	cv::line(img, pixel(s.uAt(vTop) + du, vTop), pixel(s.uAt(vBottom) + du, vBottom), c, w, cv::LINE_AA);
}

void StereoPictureDrawing::legend(cv::Mat& img, const std::vector<std::pair<std::string, cv::Scalar>>& items)
{
	const int H = img.rows;
	int x = 4;
	cv::rectangle(img, cv::Rect(0, H - 16, img.cols, 16), cv::Scalar(0, 0, 0), cv::FILLED);
	for (const auto& [text, colour] : items)
	{
		cv::line(img, {x, H - 8}, {x + 12, H - 8}, colour, 3);
		cv::putText(img, text, {x + 15, H - 4}, cv::FONT_HERSHEY_PLAIN, 0.8, cv::Scalar(255, 255, 255), 1, cv::LINE_AA);
		int base = 0;
		x += 15 + cv::getTextSize(text, cv::FONT_HERSHEY_PLAIN, 0.8, 1, &base).width + 10;
	}
}
}  // namespace featloc
