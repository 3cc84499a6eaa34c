#include "featloc/plot/CurvePlot.h"
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
// Okabe & Ito's colour-blind-safe palette (BGR), yellow left out (unreadable
// on white): series 2k and 2k+1 (a matcher with and without an option) get
// one hue, the second drawn dashed with square markers (see save()).
const cv::Scalar kPalette[] = {
	{178, 114, 0}, {0, 94, 213}, {115, 158, 0}, {167, 121, 204}, {0, 159, 230}, {0, 0, 0}};
}  // namespace

void CurvePlot::save(const std::string& pngPath, int width, int height) const
{
	cv::Mat img(height, width, CV_8UC3, cv::Scalar(255, 255, 255));
	const int left = 80, right = width - 30, top = 80, bottom = height - 70;
	const cv::Scalar axis(90, 90, 90), grid(225, 225, 225);
	const auto font = cv::FONT_HERSHEY_SIMPLEX;
	const size_t nx = std::max<size_t>(xTicks.size(), 1);
	auto px = [&](size_t i) {
		return nx == 1 ? (left + right) / 2
					   : left + 20 + static_cast<int>(i) * (right - left - 40) / static_cast<int>(nx - 1);
	};
	auto py = [&](double v) {
		const double f = (std::clamp(v, yMin, yMax) - yMin) / (yMax - yMin);
		return bottom - static_cast<int>(f * (bottom - top));
	};
	for (int k = 0; k <= 5; k++)
	{
		const double v = yMin + (yMax - yMin) * k / 5;
		cv::line(img, {left, py(v)}, {right, py(v)}, grid, 1);
		char buf[32];
		std::snprintf(buf, sizeof(buf), "%g", v);
		cv::putText(img, buf, {left - 50, py(v) + 5}, font, 0.45, axis, 1, cv::LINE_AA);
	}
	cv::rectangle(img, {left, top}, {right, bottom}, axis, 1);
	for (size_t i = 0; i < xTicks.size(); i++)
	{
		int base = 0;
		const auto sz = cv::getTextSize(xTicks[i], font, 0.45, 1, &base);
		cv::putText(img, xTicks[i], {px(i) - sz.width / 2, bottom + 22}, font, 0.45, axis, 1,
			cv::LINE_AA);
	}
	cv::putText(img, title, {left, 35}, font, 0.65, cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
	cv::putText(img, xLabel, {left, height - 20}, font, 0.5, axis, 1, cv::LINE_AA);
	cv::putText(img, yLabel, {10, top - 14}, font, 0.5, axis, 1, cv::LINE_AA);
	for (size_t s = 0; s < series.size(); s++)
	{
		const bool paired = pairedSeries && series.size() > 1;
		const cv::Scalar c =
			kPalette[(paired ? s / 2 : s) % (sizeof(kPalette) / sizeof(kPalette[0]))];
		const bool second = paired && s % 2 == 1;
		auto mark = [&](cv::Point p) {
			if (second)
				cv::rectangle(img, p - cv::Point(5, 5), p + cv::Point(5, 5), c, cv::FILLED);
			else
				cv::circle(img, p, 5, c, cv::FILLED, cv::LINE_AA);
		};
		// Dashed: every other 8-pixel piece of the segment.
		auto segment = [&](cv::Point a, cv::Point b) {
			if (!second)
			{
				cv::line(img, a, b, c, 2, cv::LINE_AA);
				return;
			}
			const double len = std::hypot(b.x - a.x, b.y - a.y);
			const int pieces = std::max(1, static_cast<int>(len / 8));
			for (int k = 0; k < pieces; k += 2)
			{
				const double f0 = static_cast<double>(k) / pieces,
							 f1 = static_cast<double>(k + 1) / pieces;
				cv::line(img, a + (b - a) * f0, a + (b - a) * f1, c, 2, cv::LINE_AA);
			}
		};
		const auto& v = series[s].values;
		for (size_t i = 0; i < v.size() && i < nx; i++)
		{
			mark({px(i), py(v[i])});
			if (i > 0) segment({px(i - 1), py(v[i - 1])}, {px(i), py(v[i])});
		}
		const int ly = bottom - 20 - static_cast<int>(series.size() - 1 - s) * 22;
		segment({left + 15, ly - 5}, {left + 45, ly - 5});
		mark({left + 30, ly - 5});
		cv::putText(img, series[s].label, {left + 52, ly}, font, 0.5, cv::Scalar(0, 0, 0), 1,
			cv::LINE_AA);
	}
	writeWholeFile(pngPath, [&](const std::string& file) {
		if (!cv::imwrite(file, img)) throw std::runtime_error("cannot write the plot '" + pngPath + "'");
	});
}
}  // namespace featloc
