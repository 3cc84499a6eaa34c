#include "featloc/output/StereoDebugPicture.h"

#include <opencv2/imgproc.hpp>

#include "featloc/output/StereoPictureDrawing.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace featloc
{
namespace
{
const cv::Scalar kDetected(150, 150, 150), kRejected(0, 140, 255), kOnPlane(0, 230, 255),
	kSelected(40, 220, 40), kBoundary(255, 80, 255), kWall(255, 230, 0);

using D = StereoPictureDrawing;

cv::Scalar planeTint(size_t k)
{
	static const cv::Scalar tints[] = {{255, 120, 60}, {60, 120, 255}, {200, 60, 200}, {60, 200, 200},
		{200, 200, 60}, {120, 60, 255}};
	return tints[k % (sizeof(tints) / sizeof(tints[0]))];
}
}  // namespace

cv::Mat StereoDebugPicture::draw(const cv::Mat& left, const StereoLandmarkFrame& f)
{
	cv::Mat img = D::toBgr(left);
	const int H = img.rows;

	// Planar regions: a translucent tint over each plane's pixels.
	size_t shown = 0;
	for (const auto& pl : f.planes)
	{
		if (pl.mask.empty() || !pl.fitted || pl.mask.size() != img.size()) continue;
		cv::Mat tint(img.size(), img.type(), planeTint(shown++));
		cv::Mat mixed;
		cv::addWeighted(img, 0.65, tint, 0.35, 0, mixed);
		mixed.copyTo(img, pl.mask);
	}
	// Segments, least interesting first so the selected ones end on top.
	for (const auto& s : f.left) D::segment(img, s, s.vTop, s.vBottom, 0, kDetected, 1);
	std::vector<bool> onPlane(f.matches.size(), false);
	for (const auto& ft : f.features)
		if (ft.match < onPlane.size()) onPlane[ft.match] = true;
	for (size_t i = 0; i < f.matches.size(); i++)
	{
		if (onPlane[i]) continue;
		const auto& m = f.matches[i];
		D::segment(img, f.left[m.left], m.vLow, m.vHigh, 0, kRejected, 1);
	}
	for (const auto& ft : f.features)
	{
		const auto& m = f.matches[ft.match];
		const auto& s = f.left[m.left];
		D::segment(img, s, s.vTop, s.vBottom, 0, ft.selected ? kSelected : kOnPlane, ft.selected ? 3 : 2);
		if (ft.selected)
			cv::putText(img, std::to_string(ft.index), D::pixel(s.uAt(s.vTop) + 3, s.vTop + 12),
				cv::FONT_HERSHEY_PLAIN, 0.9, kSelected, 1, cv::LINE_AA);
	}
	// Walls that observed the pose (featloc's wall observations): a bar
	// over the columns where the wall is seen from the predicted pose,
	// under the boundaries' lines.
	for (const auto& w : f.walls)
		for (const auto& pl : f.planes)
			if (pl.wall == w.wall && pl.visibleUMin >= 0)
			{
				cv::line(img, D::pixel(pl.visibleUMin, 6), D::pixel(pl.visibleUMax, 6), kWall, 4);
				const std::string label = "wall " + std::to_string(w.wall);
				int base = 0;
				const cv::Size sz = cv::getTextSize(label, cv::FONT_HERSHEY_PLAIN, 0.9, 1, &base);
				const cv::Point at = D::pixel(pl.visibleUMin + 2, 24);
				cv::rectangle(img, at + cv::Point(-2, base), at + cv::Point(sz.width + 2, -sz.height - 2),
					cv::Scalar(0, 0, 0), cv::FILLED);
				cv::putText(img, label, at, cv::FONT_HERSHEY_PLAIN, 0.9, kWall, 1, cv::LINE_AA);
			}
	// Boundaries: the line and its 3-sigma bars (Fig. 6).
	for (const auto& b : f.boundaries)
	{
		if (!b.found) continue;
		cv::line(img, D::pixel(b.u, 0), D::pixel(b.u, H - 1), kBoundary, 1, cv::LINE_AA);
		for (const int v : {2, H - 3})
			cv::line(img, D::pixel(b.u - 3 * b.sigma, v), D::pixel(b.u + 3 * b.sigma, v), kBoundary, 2, cv::LINE_AA);
	}
	// Legend.
	D::legend(img, {{"detected", kDetected}, {"matched, rejected", kRejected}, {"on plane", kOnPlane},
								 {"selected", kSelected}, {"boundary 3 sigma", kBoundary}, {"wall obs.", kWall}});
	return img;
}
}  // namespace featloc
