#include "featloc/stereo/VerticalSegmentDetector.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>

#include "featloc/config/ConfigValues.h"

namespace featloc
{
namespace
{
struct EdgePixel
{
	double u;
	int v;
	float g;  //!< signed dI/du
};

struct Chain
{
	std::vector<EdgePixel> pixels;
	int polarity;
	double lastU() const { return pixels.back().u; }
	int lastV() const { return pixels.back().v; }
};
}  // namespace

void VerticalSegmentDetector::Options::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	using namespace featloc::config;
	read(c, s, "smoothing_sigma", smoothing_sigma);
	read(c, s, "min_gradient", min_gradient);
	read(c, s, "min_length_px", min_length_px);
	read(c, s, "max_tilt_deg", max_tilt_deg);
	read(c, s, "max_gap_rows", max_gap_rows);
	read(c, s, "max_step_px", max_step_px);
	require(smoothing_sigma >= 0 && smoothing_sigma <= 10, c, s, "smoothing_sigma", "in [0, 10] px");
	require(min_gradient > 0, c, s, "min_gradient", "> 0");
	require(min_length_px >= 3, c, s, "min_length_px", ">= 3");
	require(max_tilt_deg >= 0 && max_tilt_deg < 45, c, s, "max_tilt_deg", "in [0, 45)");
	require(max_gap_rows >= 0 && max_gap_rows <= 20, c, s, "max_gap_rows", "in [0, 20]");
	require(max_step_px > 0 && max_step_px <= 5, c, s, "max_step_px", "in (0, 5]");
}

void VerticalSegmentDetector::Options::saveToConfigFile(
	mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	using namespace featloc::config;
	write(c, s, "smoothing_sigma", smoothing_sigma, "[px] Gaussian smoothing before the derivative");
	write(c, s, "min_gradient", min_gradient, "[grey levels/px] weakest edge kept (|dI/du|)");
	write(c, s, "min_length_px", min_length_px, "[px] shortest segment");
	write(c, s, "max_tilt_deg", max_tilt_deg, "[deg] most a segment may lean from vertical");
	write(c, s, "max_gap_rows", max_gap_rows, "[rows] gap bridged inside a segment");
	write(c, s, "max_step_px", max_step_px, "[px] column change between chained rows");
}

std::vector<VerticalSegment> VerticalSegmentDetector::detect(const cv::Mat& grey) const
{
	cv::Mat f;
	grey.convertTo(f, CV_32F);
	if (options.smoothing_sigma > 0) cv::GaussianBlur(f, f, cv::Size(0, 0), options.smoothing_sigma);
	cv::Mat gx;
	// Sobel's 3x3 kernel sums 8 differences of one pixel: /8 gives dI/du.
	cv::Sobel(f, gx, CV_32F, 1, 0, 3, 1.0 / 8.0);

	const float thr = static_cast<float>(options.min_gradient);
	std::vector<Chain> chains;
	std::vector<size_t> active;	 // indices of open chains
	std::vector<VerticalSegment> out;
	const double maxSlope = std::tan(options.max_tilt_deg * M_PI / 180.0);

	auto close = [&](const Chain& c) {
		const auto& p = c.pixels;
		const double len = p.back().v - p.front().v + 1;
		if (len < options.min_length_px) return;
		// Least-squares column fit u = u0 + k (v - vMid).
		const double vMid = 0.5 * (p.front().v + p.back().v);
		double sv = 0, su = 0, svv = 0, svu = 0, sg = 0;
		for (const auto& e : p)
		{
			const double dv = e.v - vMid;
			sv += dv, su += e.u, svv += dv * dv, svu += dv * e.u, sg += std::abs(e.g);
		}
		const double n = static_cast<double>(p.size());
		const double den = n * svv - sv * sv;
		const double k = den > 1e-12 ? (n * svu - sv * su) / den : 0.0;
		const double u0 = (su - k * sv) / n;
		if (std::abs(k) > maxSlope) return;
		double r2 = 0;
		for (const auto& e : p)
		{
			const double r = e.u - (u0 + k * (e.v - vMid));
			r2 += r * r;
		}
		VerticalSegment s;
		s.u = u0;
		s.slope = k;
		s.vTop = p.front().v;
		s.vBottom = p.back().v;
		s.polarity = c.polarity;
		s.contrast = sg / n;
		s.residual = std::sqrt(r2 / n);
		s.pixels = p.size();
		out.push_back(s);
	};

	std::vector<EdgePixel> row;
	std::vector<char> taken;
	for (int v = 0; v < gx.rows; v++)
	{
		const float* g = gx.ptr<float>(v);
		row.clear();
		for (int u = 1; u + 1 < gx.cols; u++)
		{
			const float a = std::abs(g[u - 1]), b = std::abs(g[u]), c = std::abs(g[u + 1]);
			if (b < thr || b < a || b <= c) continue;
			// The maximum of a parabola through the three |g|.
			const float den = a - 2 * b + c;
			const double off = den < -1e-6f ? 0.5 * (a - c) / den : 0.0;
			row.push_back({u + off, v, g[u]});
		}
		// Each open chain takes the nearest pixel of its polarity.
		taken.assign(row.size(), 0);
		std::vector<size_t> still;
		for (size_t ci : active)
		{
			Chain& c = chains[ci];
			if (v - c.lastV() > options.max_gap_rows + 1)
			{
				close(c);
				continue;
			}
			// Pixels are in column order: binary search around the chain's column.
			const double uc = c.lastU();
			auto it = std::lower_bound(row.begin(), row.end(), uc - options.max_step_px,
				[](const EdgePixel& e, double x) { return e.u < x; });
			long best = -1;
			double bestD = options.max_step_px;
			for (; it != row.end() && it->u <= uc + options.max_step_px; ++it)
			{
				const auto k = static_cast<size_t>(it - row.begin());
				if (taken[k] || (it->g > 0 ? 1 : -1) != c.polarity) continue;
				const double d = std::abs(it->u - uc);
				if (d <= bestD) bestD = d, best = static_cast<long>(k);
			}
			if (best >= 0)
			{
				taken[static_cast<size_t>(best)] = 1;
				c.pixels.push_back(row[static_cast<size_t>(best)]);
			}
			still.push_back(ci);
		}
		active.swap(still);
		for (size_t k = 0; k < row.size(); k++)
			if (!taken[k])
			{
				Chain c;
				c.polarity = row[k].g > 0 ? 1 : -1;
				c.pixels.push_back(row[k]);
				chains.push_back(std::move(c));
				active.push_back(chains.size() - 1);
			}
	}
	for (size_t ci : active) close(chains[ci]);
	std::sort(out.begin(), out.end(), [](const VerticalSegment& a, const VerticalSegment& b) {
		return a.u < b.u;
	});
	return out;
}
}  // namespace featloc
