#include "featloc/plot/PlotCanvas.h"
#include "featloc/core/WholeFile.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace featloc
{
namespace
{
constexpr int kMarginPx = 70;

/** 1, 2 or 5 times a power of ten, about span/8. */
double niceStep(double span)
{
	const double raw = span / 8;
	const double p = std::pow(10.0, std::floor(std::log10(raw)));
	for (double m : {1.0, 2.0, 5.0})
		if (m * p >= raw) return m * p;
	return 10 * p;
}

cv::Scalar bgr(PlotCanvas::Rgb c) { return cv::Scalar(c.b, c.g, c.r); }
}  // namespace

struct PlotCanvas::Impl
{
	cv::Mat img;
	int width = 0, height = 0;
	double cx = 0, cy = 0, scale = 1, span = 1;
	int legendRows = 0;

	cv::Point px(const Point& p) const
	{
		return {static_cast<int>(std::lround(width / 2 + (p.x - cx) * scale)),
			static_cast<int>(std::lround(height / 2 - (p.y - cy) * scale))};
	}
};

PlotCanvas::PlotCanvas(double minX, double minY, double maxX, double maxY, int sizePx)
	: m(std::make_unique<Impl>())
{
	// The longer side gets sizePx pixels; the other keeps the aspect ratio
	// (at least 500 px, room for the legend), same scale on both axes.
	const double spanX = std::max(maxX - minX, 1.0), spanY = std::max(maxY - minY, 1.0);
	m->span = std::max(spanX, spanY);
	m->cx = (minX + maxX) / 2;
	m->cy = (minY + maxY) / 2;
	m->scale = (sizePx - 2 * kMarginPx) / m->span;
	m->width = std::max(500, static_cast<int>(spanX * m->scale) + 2 * kMarginPx);
	m->height = std::max(500, static_cast<int>(spanY * m->scale) + 2 * kMarginPx + 60);
	m->img = cv::Mat(m->height, m->width, CV_8UC3, cv::Scalar(255, 255, 255));

	const double step = niceStep(m->span);
	const cv::Scalar grid(225, 225, 225), text(90, 90, 90);
	const int left = kMarginPx / 2, right = m->width - kMarginPx / 2;
	const int top = kMarginPx / 2 + 30, bottom = m->height - kMarginPx / 2;
	const double halfW = (m->width / 2.0) / m->scale, halfH = (m->height / 2.0) / m->scale;
	for (double x = std::floor((m->cx - halfW) / step) * step; x <= m->cx + halfW; x += step)
	{
		const int u = m->px({x, m->cy}).x;
		if (u < left || u > right) continue;
		cv::line(m->img, {u, top}, {u, bottom}, grid, 1);
		char label[32];
		std::snprintf(label, sizeof(label), "%g", x);
		cv::putText(m->img, label, {u + 2, bottom + 16}, cv::FONT_HERSHEY_SIMPLEX,
			0.4, text, 1, cv::LINE_AA);
	}
	for (double y = std::floor((m->cy - halfH) / step) * step; y <= m->cy + halfH; y += step)
	{
		const int v = m->px({m->cx, y}).y;
		if (v < top || v > bottom) continue;
		cv::line(m->img, {left, v}, {right, v}, grid, 1);
		char label[32];
		std::snprintf(label, sizeof(label), "%g", y);
		cv::putText(m->img, label, {4, v - 2}, cv::FONT_HERSHEY_SIMPLEX, 0.4, text,
			1, cv::LINE_AA);
	}
	char scaleText[64];
	std::snprintf(scaleText, sizeof(scaleText), "grid %g m", step);
	cv::putText(m->img, scaleText, {left, m->height - 6}, cv::FONT_HERSHEY_SIMPLEX,
		0.45, text, 1, cv::LINE_AA);
}

PlotCanvas::~PlotCanvas() = default;

void PlotCanvas::line(const Point& a, const Point& b, Rgb colour, int thicknessPx)
{
	cv::line(m->img, m->px(a), m->px(b), bgr(colour), thicknessPx, cv::LINE_AA);
}

void PlotCanvas::polyline(const std::vector<Point>& pts, Rgb colour, int thicknessPx)
{
	for (size_t i = 1; i < pts.size(); i++) line(pts[i - 1], pts[i], colour, thicknessPx);
}

void PlotCanvas::circle(const Point& c, double radiusMetres, Rgb colour, bool filled)
{
	const int r = std::max(1, static_cast<int>(std::lround(radiusMetres * m->scale)));
	cv::circle(m->img, m->px(c), r, bgr(colour), filled ? cv::FILLED : 2, cv::LINE_AA);
}

void PlotCanvas::marker(const Point& c, Rgb colour, int radiusPx)
{
	cv::circle(m->img, m->px(c), radiusPx, bgr(colour), 2, cv::LINE_AA);
}

void PlotCanvas::dots(const std::vector<Point>& pts, Rgb colour)
{
	for (const auto& p : pts)
	{
		const cv::Point q = m->px(p);
		if (q.x >= 0 && q.y >= 0 && q.x < m->width && q.y < m->height)
			m->img.at<cv::Vec3b>(q) = cv::Vec3b(
				static_cast<uchar>(colour.b), static_cast<uchar>(colour.g),
				static_cast<uchar>(colour.r));
	}
}

void PlotCanvas::title(const std::string& text)
{
	cv::putText(m->img, text, {kMarginPx / 2, 28}, cv::FONT_HERSHEY_SIMPLEX, 0.6,
		cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
}

void PlotCanvas::legend(const std::string& text, Rgb colour)
{
	// Legend rows go left to right along the top, under the title.
	const int x = kMarginPx / 2 + 230 * (m->legendRows % 4);
	const int y = 52 + 22 * (m->legendRows / 4);
	m->legendRows++;
	cv::line(m->img, {x, y}, {x + 30, y}, bgr(colour), 3);
	cv::putText(m->img, text, {x + 40, y + 5}, cv::FONT_HERSHEY_SIMPLEX, 0.5,
		cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
}

void PlotCanvas::save(const std::string& pngPath) const
{
	writeWholeFile(pngPath, [&](const std::string& file) {
		if (!cv::imwrite(file, m->img)) throw std::runtime_error("cannot write plot '" + pngPath + "'");
	});
}
}  // namespace featloc
