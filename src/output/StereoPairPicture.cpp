#include "featloc/output/StereoPairPicture.h"

#include <opencv2/imgproc.hpp>

#include <cmath>
#include <string>

#include "featloc/output/StereoPictureDrawing.h"

namespace featloc
{
namespace
{
const cv::Scalar kDetected(150, 150, 150), kRejected(0, 140, 255), kSupported(40, 220, 40);

using D = StereoPictureDrawing;
}  // namespace

cv::Mat StereoPairPicture::draw(const cv::Mat& left, const cv::Mat& right, const StereoVerticalLines::Result& r)
{
	cv::Mat img;
	cv::hconcat(D::toBgr(left), D::toBgr(right), img);
	const double W = left.cols;
	for (const auto& s : r.left) D::segment(img, s, s.vTop, s.vBottom, 0, kDetected, 1);
	for (const auto& s : r.right) D::segment(img, s, s.vTop, s.vBottom, W, kDetected, 1);
	std::vector<double> depth(r.matches.size(), -1);
	for (const auto& l : r.lines) depth[l.match] = l.depth;
	int number = 0;
	for (size_t i = 0; i < r.matches.size(); i++)
	{
		const auto& m = r.matches[i];
		const bool ok = r.matchRejection[i].empty();
		const auto& c = ok ? kSupported : kRejected;
		const auto &sl = r.left[m.left], &sr = r.right[m.right];
		D::segment(img, sl, m.vLow, m.vHigh, 0, c, ok ? 2 : 1);
		D::segment(img, sr, m.vLow, m.vHigh, W, c, ok ? 2 : 1);
		if (!ok || depth[i] < 0) continue;
		// The same number beside the segment in both images says which
		// matched which (lines across the pair hid the scene).
		const std::string text = std::to_string(++number);
		cv::putText(img, text, D::pixel(sl.uAt(m.vLow) + 2, m.vLow - 2), cv::FONT_HERSHEY_PLAIN, 0.8, kSupported, 1,
			cv::LINE_AA);
		cv::putText(img, text, D::pixel(sr.uAt(m.vLow) + W + 2, m.vLow - 2), cv::FONT_HERSHEY_PLAIN, 0.8, kSupported, 1,
			cv::LINE_AA);
	}
	D::legend(img, {{"detected", kDetected}, {"matched, no SAD support", kRejected},
								 {"matched and supported (number: the vertical line in both images)", kSupported}});
	return img;
}
}  // namespace featloc
