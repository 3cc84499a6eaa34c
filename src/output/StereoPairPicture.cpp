#include "featloc/output/StereoPairPicture.h"

#include <opencv2/imgproc.hpp>

#include <cmath>
#include <string>

#include "featloc/output/PictureLegend.h"

namespace featloc
{
namespace
{
const cv::Scalar kDetected(150, 150, 150), kRejected(0, 140, 255), kSupported(40, 220, 40);

cv::Point px(double u, double v) { return {static_cast<int>(std::lround(u)), static_cast<int>(std::lround(v))}; }

cv::Mat bgr(const cv::Mat& m)
{
	cv::Mat out;
	if (m.channels() == 1)
		cv::cvtColor(m, out, cv::COLOR_GRAY2BGR);
	else
		out = m.clone();
	return out;
}
}  // namespace

cv::Mat StereoPairPicture::draw(const cv::Mat& left, const cv::Mat& right, const StereoVerticalLines::Result& r)
{
	cv::Mat img;
	cv::hconcat(bgr(left), bgr(right), img);
	const double W = left.cols;
	auto seg = [&](const VerticalSegment& s, double vTop, double vBottom, double du, const cv::Scalar& c, int w)
	{ cv::line(img, px(s.uAt(vTop) + du, vTop), px(s.uAt(vBottom) + du, vBottom), c, w, cv::LINE_AA); };
	for (const auto& s : r.left) seg(s, s.vTop, s.vBottom, 0, kDetected, 1);
	for (const auto& s : r.right) seg(s, s.vTop, s.vBottom, W, kDetected, 1);
	std::vector<double> depth(r.matches.size(), -1);
	for (const auto& l : r.lines) depth[l.match] = l.depth;
	int number = 0;
	for (size_t i = 0; i < r.matches.size(); i++)
	{
		const auto& m = r.matches[i];
		const bool ok = r.matchRejection[i].empty();
		const auto& c = ok ? kSupported : kRejected;
		const auto &sl = r.left[m.left], &sr = r.right[m.right];
		seg(sl, m.vLow, m.vHigh, 0, c, ok ? 2 : 1);
		seg(sr, m.vLow, m.vHigh, W, c, ok ? 2 : 1);
		if (!ok || depth[i] < 0) continue;
		// The same number beside the segment in both images says which
		// matched which (lines across the pair hid the scene).
		const std::string text = std::to_string(++number);
		cv::putText(img, text, px(sl.uAt(m.vLow) + 2, m.vLow - 2), cv::FONT_HERSHEY_PLAIN, 0.8, kSupported, 1,
			cv::LINE_AA);
		cv::putText(img, text, px(sr.uAt(m.vLow) + W + 2, m.vLow - 2), cv::FONT_HERSHEY_PLAIN, 0.8, kSupported, 1,
			cv::LINE_AA);
	}
	PictureLegend::draw(img, {{"detected", kDetected}, {"matched, no SAD support", kRejected},
								 {"matched and supported (number: the vertical line in both images)", kSupported}});
	return img;
}
}  // namespace featloc
