#include "featloc/eval/TrajectoryPlot.h"

#include <mrpt/poses/CPose2D.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <vector>

namespace featloc
{
namespace
{
constexpr int kSize = 1000;	 // canvas side [px]
constexpr int kMargin = 70;	 // [px]

/** 1, 2 or 5 times a power of ten, about span/8. */
double niceStep(double span)
{
	const double raw = span / 8;
	const double p = std::pow(10.0, std::floor(std::log10(raw)));
	for (double m : {1.0, 2.0, 5.0})
		if (m * p >= raw) return m * p;
	return 10 * p;
}

std::vector<cv::Point2d> positions(
	const Trajectory& t, const mrpt::poses::CPose2D& transform)
{
	std::vector<cv::Point2d> out;
	for (const auto& p : t.poses)
	{
		const auto q = transform + mrpt::poses::CPose2D(p.pose);
		out.emplace_back(q.x(), q.y());
	}
	return out;
}
}  // namespace

void TrajectoryPlot::write(
	const std::string& pngPath, const Trajectory& reference,
	const Trajectory& estimate, const mrpt::math::TPose2D& alignment,
	const std::string& title)
{
	const auto ref = positions(reference, mrpt::poses::CPose2D());
	const auto est = positions(estimate, mrpt::poses::CPose2D(alignment));

	double minX = 1e300, maxX = -1e300, minY = 1e300, maxY = -1e300;
	for (const auto* v : {&ref, &est})
		for (const auto& p : *v)
		{
			minX = std::min(minX, p.x);
			maxX = std::max(maxX, p.x);
			minY = std::min(minY, p.y);
			maxY = std::max(maxY, p.y);
		}
	const double span = std::max({maxX - minX, maxY - minY, 1.0});
	const double cx = (minX + maxX) / 2, cy = (minY + maxY) / 2;
	const double scale = (kSize - 2 * kMargin) / span;	// px per metre
	auto px = [&](const cv::Point2d& p) {
		return cv::Point(
			static_cast<int>(kSize / 2 + (p.x - cx) * scale),
			static_cast<int>(kSize / 2 - (p.y - cy) * scale));
	};

	cv::Mat img(kSize, kSize, CV_8UC3, cv::Scalar(255, 255, 255));
	const double step = niceStep(span);
	const cv::Scalar gridColor(225, 225, 225), textColor(90, 90, 90);
	for (double x = std::floor((cx - span / 2) / step) * step;
		 x <= cx + span / 2 + step; x += step)
	{
		const int u = px({x, cy}).x;
		if (u < kMargin / 2 || u > kSize - kMargin / 2) continue;
		cv::line(img, {u, kMargin / 2}, {u, kSize - kMargin / 2}, gridColor, 1);
		char label[32];
		std::snprintf(label, sizeof(label), "%g", x);
		cv::putText(
			img, label, {u + 2, kSize - kMargin / 2 + 16},
			cv::FONT_HERSHEY_SIMPLEX, 0.4, textColor, 1, cv::LINE_AA);
	}
	for (double y = std::floor((cy - span / 2) / step) * step;
		 y <= cy + span / 2 + step; y += step)
	{
		const int v = px({cx, y}).y;
		if (v < kMargin / 2 || v > kSize - kMargin / 2) continue;
		cv::line(img, {kMargin / 2, v}, {kSize - kMargin / 2, v}, gridColor, 1);
		char label[32];
		std::snprintf(label, sizeof(label), "%g", y);
		cv::putText(
			img, label, {4, v - 2}, cv::FONT_HERSHEY_SIMPLEX, 0.4, textColor,
			1, cv::LINE_AA);
	}

	const cv::Scalar refColor(40, 160, 40), estColor(30, 30, 220);	// BGR
	auto polyline = [&](const std::vector<cv::Point2d>& pts, cv::Scalar col) {
		for (size_t i = 1; i < pts.size(); i++)
			cv::line(img, px(pts[i - 1]), px(pts[i]), col, 2, cv::LINE_AA);
		if (!pts.empty()) cv::circle(img, px(pts.front()), 6, col, 2, cv::LINE_AA);
	};
	polyline(ref, refColor);
	polyline(est, estColor);

	cv::putText(
		img, title, {kMargin / 2, 28}, cv::FONT_HERSHEY_SIMPLEX, 0.6,
		cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
	const int lx = kSize - 300, ly = 50;
	cv::line(img, {lx, ly}, {lx + 30, ly}, refColor, 3);
	cv::putText(
		img, "reference", {lx + 40, ly + 5}, cv::FONT_HERSHEY_SIMPLEX, 0.5,
		cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
	cv::line(img, {lx, ly + 22}, {lx + 30, ly + 22}, estColor, 3);
	cv::putText(
		img, "estimate (aligned)", {lx + 40, ly + 27},
		cv::FONT_HERSHEY_SIMPLEX, 0.5, cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
	char scaleText[64];
	std::snprintf(scaleText, sizeof(scaleText), "grid: %g m, circle = start", step);
	cv::putText(
		img, scaleText, {lx, ly + 50}, cv::FONT_HERSHEY_SIMPLEX, 0.45,
		textColor, 1, cv::LINE_AA);

	if (!cv::imwrite(pngPath, img))
		throw std::runtime_error("cannot write plot '" + pngPath + "'");
}
}  // namespace featloc
