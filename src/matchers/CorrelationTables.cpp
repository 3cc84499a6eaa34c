#include "featloc/matchers/CorrelationTables.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <opencv2/imgproc.hpp>
#include <limits>
#include <queue>

namespace featloc
{
namespace
{
/** Cells d[i] farther than m[i] take m[i] and, in t[i], its value val[i].
 * A value falls with its distance, so the nearest disc's value is the
 * largest: a minimum and a maximum, vectorized, where comparisons would
 * branch in an order no predictor follows. */
void lowerRun(const float* __restrict m, const float* __restrict val, float* __restrict d,
	float* __restrict t, int len)
{
	for (int i = 0; i < len; i++)
	{
		d[i] = std::min(d[i], m[i]);
		t[i] = std::max(t[i], val[i]);
	}
}
}  // namespace

int CorrelationTables::topLevelFor(double halfWindow, double resolution)
{
	const int cellsAcross = 2 * static_cast<int>(std::ceil(halfWindow / resolution)) + 1;
	int top = 0;
	while (top < kMaxLevel && 2 * (1 << top) < cellsAcross) top++;
	return top;
}

double CorrelationTables::rotationStep(
	const std::vector<double>& px, const std::vector<double>& py, double resolution)
{
	std::vector<double> ranges(px.size());
	for (size_t i = 0; i < px.size(); i++) ranges[i] = std::hypot(px[i], py[i]);
	if (ranges.empty()) return resolution;
	auto p95 = ranges.begin() + static_cast<long>((ranges.size() - 1) * 95 / 100);
	std::nth_element(ranges.begin(), p95, ranges.end());
	return resolution / std::max(*p95, resolution);
}

void CorrelationTables::build(int width, int height, double x0, double y0, double res,
	double hitSigma, int top, const std::function<void(cv::Mat& surface)>& drawSurface)
{
	cv::Mat surface = prepare(width, height, x0, y0, res, top, drawSurface);
	cv::Mat distance;
	cv::distanceTransform(surface, distance, cv::DIST_L2, cv::DIST_MASK_PRECISE, CV_32F);
	cv::Mat metres(m_height, m_width, CV_32F, m_distance.data());
	distance.convertTo(metres, CV_32F, res);
	cv::Mat table(m_height, m_width, CV_32F, m_table.data());
	// exp(-d^2 / 2 sigma^2), d in metres.
	const double k = -0.5 * (res / hitSigma) * (res / hitSigma);
	cv::multiply(distance, distance, distance, k);
	cv::exp(distance, table);
	buildLevels();
}

void CorrelationTables::buildNear(int width, int height, double x0, double y0, double res,
	double hitSigma, int top, double maxDistance,
	const std::function<void(cv::Mat& surface)>& drawSurface)
{
	cv::Mat surface = prepare(width, height, x0, y0, res, top, drawSurface);
	// The cells within maxDistance of a surface pixel, with their distance
	// in pixels as the exact transform measures it (centre to centre), and
	// what that distance puts in the tables (the same expressions as build):
	// one run of cells per row of the disc, its distances and values in a
	// row of their own, so that a pixel's disc is written run by run.
	const int R = static_cast<int>(std::floor(maxDistance / res));
	const double k = -0.5 * (res / hitSigma) * (res / hitSigma);
	struct Run
	{
		int dv, half;  // cells du = -half..half of row dv
		size_t first;  // index of du = -half in metres and values
	};
	std::vector<Run> runs;
	std::vector<float> metres, values;
	for (int dv = -R; dv <= R; dv++)
	{
		int half = 0;
		while ((half + 1) * (half + 1) + dv * dv <= R * R) half++;
		runs.push_back({dv, half, metres.size()});
		for (int du = -half; du <= half; du++)
		{
			const float d = std::sqrt(static_cast<float>(du * du + dv * dv));
			metres.push_back(static_cast<float>(d * res));
			values.push_back(std::exp(static_cast<float>(d * d * k)));
		}
	}
	std::fill(m_distance.begin(), m_distance.end(), std::numeric_limits<float>::infinity());
	std::fill(m_table.begin(), m_table.end(), 0.0f);
	// Each cell ends with the least distance of the discs over it and that
	// distance's value, whatever the order the discs are written in (a
	// distance has one value).
	float* dist = m_distance.data();
	float* table = m_table.data();
	const size_t W = static_cast<size_t>(m_width);
	for (int v = 0; v < m_height; v++)
	{
		const uint8_t* row = surface.ptr<uint8_t>(v);
		for (const uint8_t* at = row; (at = static_cast<const uint8_t*>(
										   std::memchr(at, 0, W - static_cast<size_t>(at - row))));
			 at++)
		{
			const int u = static_cast<int>(at - row);
			for (const auto& r : runs)
			{
				const int rv = v + r.dv;
				if (rv < 0 || rv >= m_height) continue;
				const int lo = std::max(u - r.half, 0), hi = std::min(u + r.half, m_width - 1);
				const size_t from = r.first + static_cast<size_t>(lo - (u - r.half));
				const size_t cell = static_cast<size_t>(rv) * W + static_cast<size_t>(lo);
				lowerRun(metres.data() + from, values.data() + from, dist + cell, table + cell,
					hi - lo + 1);
			}
		}
	}
	buildLevels();
}

cv::Mat CorrelationTables::prepare(int width, int height, double x0, double y0, double res,
	int top, const std::function<void(cv::Mat& surface)>& drawSurface)
{
	m_width = width;
	m_height = height;
	m_x0 = x0;
	m_y0 = y0;
	m_resolution = res;
	m_top = top;
	cv::Mat surface(m_height, m_width, CV_8U, cv::Scalar(255));
	drawSurface(surface);
	const size_t cells = static_cast<size_t>(m_width) * static_cast<size_t>(m_height);
	m_distance.resize(cells);
	m_table.resize(cells);  // every cell is written by the build
	m_bounds.resize(static_cast<size_t>(m_top) + 1);  // [0]: level 0's, level 1's first step
	for (auto& t : m_bounds) t.resize(cells);
	return surface;
}

void CorrelationTables::buildLevels()
{
	// Level 0 rounded up to bytes (x 255 (1 + 1e-6): the float product's
	// two roundings, 2 x 2^-24 relative, cannot take it below 255 v): since
	// rounding up keeps the order, the maxima of the rounded values are the
	// rounded maxima, and the levels are built from bytes.
	const size_t cells = m_table.size();
	const float* __restrict table = m_table.data();
	uint8_t* __restrict q0 = m_bounds[0].data();
	const float up = static_cast<float>(kBoundScale * (1 + 1e-6));
	for (size_t c = 0; c < cells; c++)
	{
		const float t = table[c] * up;	// >= 0
		float q = static_cast<float>(static_cast<int>(t));
		q += q < t ? 1.0f : 0.0f;
		q0[c] = static_cast<uint8_t>(static_cast<int>(std::min(q, 255.0f)));
	}
	// Level L + 1 is the maximum of four shifted level-L views: one pass per
	// level (the tables of a real log's scan are millions of cells, and a
	// copy and three in-place maxima read and wrote each of them 11 times).
	// Cells within 2^L of the high edges keep level L's value.
	const size_t W = static_cast<size_t>(m_width);
	for (int L = 0; L < m_top; L++)
	{
		const size_t sft = size_t{1} << L;
		const uint8_t* src = m_bounds[static_cast<size_t>(L)].data();
		uint8_t* dst = m_bounds[static_cast<size_t>(L) + 1].data();
		for (size_t v = 0; v < static_cast<size_t>(m_height); v++)
		{
			const uint8_t* a = src + v * W;
			uint8_t* out = dst + v * W;
			if (v + sft >= static_cast<size_t>(m_height) || sft >= W)
			{
				std::copy(a, a + W, out);
				continue;
			}
			const uint8_t* b = a + sft * W;
			const size_t inner = W - sft;
			for (size_t u = 0; u < inner; u++)
				out[u] = std::max(std::max(a[u], a[u + sft]), std::max(b[u], b[u + sft]));
			std::copy(a + inner, a + W, out + inner);
		}
	}
}

std::vector<CorrelationTables::Candidate> CorrelationTables::search(
	const std::vector<double>& px, const std::vector<double>& py, const Window& win,
	double keepRatio, const std::function<bool(const mrpt::poses::CPose2D&)>& excluded) const
{
	const double res = m_resolution;
	const size_t n = px.size();
	const int nYaw = win.nYaw, nx = win.nx, ny = win.ny;
	const double gx = win.centre.x(), gy = win.centre.y(), gw = win.centre.phi();

	// Each rotation's points as table cells at the centre's translation; a
	// candidate translation adds whole cells to them.
	const int yaws = 2 * nYaw + 1;
	std::vector<int> cu(static_cast<size_t>(yaws) * n), cv(static_cast<size_t>(yaws) * n);
	for (int w = 0; w < yaws; w++)
	{
		const double th = gw + (w - nYaw) * win.yawStep;
		const double c = std::cos(th), s = std::sin(th);
		for (size_t i = 0; i < n; i++)
		{
			const double x = c * px[i] - s * py[i] + gx, y = s * px[i] + c * py[i] + gy;
			cu[static_cast<size_t>(w) * n + i] = static_cast<int>(std::floor((x - m_x0) / res));
			cv[static_cast<size_t>(w) * n + i] = static_cast<int>(std::floor((y - m_y0) / res));
		}
	}
	// For the bounds: each rotation's points that every translation of the
	// window keeps on the tables, as cell indices at the centre's (read
	// without checks), and the others (checked). Byte sums are exact in any
	// order; level 0's float sums keep the points' order.
	const long W = m_width;
	// (Tables beyond int32's cells, a map of 100 km^2 at 5 cm, are read checked.)
	const bool indexable = static_cast<long>(m_height) * W <= std::numeric_limits<int32_t>::max();
	std::vector<int32_t> inside(static_cast<size_t>(yaws) * n);
	std::vector<uint32_t> edge(static_cast<size_t>(yaws) * n);
	std::vector<size_t> insideCount(static_cast<size_t>(yaws));	// the rest: n - it
	for (int w = 0; w < yaws; w++)
	{
		const size_t base = static_cast<size_t>(w) * n;
		size_t ni = 0, ne = 0;
		for (size_t i = 0; i < n; i++)
		{
			const int u = cu[base + i], v = cv[base + i];
			if (indexable && u - nx >= 0 && u + nx < m_width && v - ny >= 0 && v + ny < m_height)
				inside[base + ni++] = static_cast<int32_t>(v * W + u);
			else
				edge[base + ne++] = static_cast<uint32_t>(i);
		}
		insideCount[static_cast<size_t>(w)] = ni;
	}
	// Mean table value under rotation w's points moved by (dx, dy) cells:
	// at level L, a bound for the block of 2^L x 2^L translations from there
	// (its bytes summed exactly, and nudged up by more than the division's
	// rounding, so that it bounds level 0's mean of the same cells).
	auto score = [&](int level, int w, int dx, int dy) {
		const size_t base = static_cast<size_t>(w) * n;
		if (level == 0)
		{
			double sum = 0;
			for (size_t i = 0; i < n; i++)
			{
				const long c = cellIndex(cu[base + i] + dx, cv[base + i] + dy);
				if (c >= 0) sum += m_table[static_cast<size_t>(c)];
			}
			return sum / static_cast<double>(n);
		}
		const uint8_t* t = m_bounds[static_cast<size_t>(level)].data();
		const long off = dy * W + dx;
		const int32_t* in = inside.data() + base;
		const size_t ni = insideCount[static_cast<size_t>(w)];
		uint32_t s0 = 0, s1 = 0;
		size_t j = 0;
		for (; j + 1 < ni; j += 2)
		{
			s0 += t[in[j] + off];
			s1 += t[in[j + 1] + off];
		}
		if (j < ni) s0 += t[in[j] + off];
		const uint32_t* e = edge.data() + base;
		for (size_t k = 0; k < n - ni; k++)
		{
			const long c = cellIndex(cu[base + e[k]] + dx, cv[base + e[k]] + dy);
			if (c >= 0) s0 += t[static_cast<size_t>(c)];
		}
		return (s0 + s1) / (kBoundScale * static_cast<double>(n)) * (1 + 1e-12);
	};

	struct Node
	{
		double bound;
		int level, yaw, dx, dy;	 // dx, dy: the block's lowest cell offset
		bool operator<(const Node& o) const { return bound < o.bound; }
	};
	std::priority_queue<Node> open;
	const int side = 1 << m_top;
	for (int w = 0; w < yaws; w++)
		for (int bx = -nx; bx <= nx; bx += side)
			for (int by = -ny; by <= ny; by += side)
				open.push({score(m_top, w, bx, by), m_top, w, bx, by});

	std::vector<Candidate> found;  // every full-resolution pose taken from the queue
	double best = 0;
	while (!open.empty())
	{
		const Node nd = open.top();
		if (nd.bound <= 0 || nd.bound < keepRatio * best) break;
		open.pop();
		if (nd.level == 0)
		{
			const mrpt::poses::CPose2D pose(
				gx + nd.dx * res, gy + nd.dy * res, gw + (nd.yaw - nYaw) * win.yawStep);
			if (excluded && excluded(pose)) continue;
			best = std::max(best, nd.bound);
			found.push_back({pose, nd.bound});
			continue;
		}
		const int half = 1 << (nd.level - 1);
		for (int cx = nd.dx; cx < nd.dx + 2 * half && cx <= nx; cx += half)
			for (int cy = nd.dy; cy < nd.dy + 2 * half && cy <= ny; cy += half)
				open.push({score(nd.level - 1, nd.yaw, cx, cy), nd.level - 1, nd.yaw, cx, cy});
	}
	// Best first; equal scores by rotation, then translation, so that the
	// order is the poses' own and not the queue's (whose pops follow the
	// bounds above level 0).
	std::sort(found.begin(), found.end(), [](const Candidate& a, const Candidate& c) {
		if (a.score != c.score) return a.score > c.score;
		if (a.pose.phi() != c.pose.phi()) return a.pose.phi() < c.pose.phi();
		if (a.pose.x() != c.pose.x()) return a.pose.x() < c.pose.x();
		return a.pose.y() < c.pose.y();
	});
	return found;
}

double CorrelationTables::score(const std::vector<double>& px, const std::vector<double>& py,
	const mrpt::poses::CPose2D& pose) const
{
	if (px.empty() || m_table.empty()) return 0;
	const double c = std::cos(pose.phi()), s = std::sin(pose.phi());
	const auto& t = m_table;
	double sum = 0;
	for (size_t i = 0; i < px.size(); i++)
	{
		const double x = c * px[i] - s * py[i] + pose.x(), y = s * px[i] + c * py[i] + pose.y();
		const long cell = cellIndex(static_cast<int>(std::floor((x - m_x0) / m_resolution)),
			static_cast<int>(std::floor((y - m_y0) / m_resolution)));
		if (cell >= 0) sum += t[static_cast<size_t>(cell)];
	}
	return sum / static_cast<double>(px.size());
}

double CorrelationTables::distanceAt(double x, double y) const
{
	if (m_distance.empty()) return -1;
	const long cell = cellIndex(static_cast<int>(std::floor((x - m_x0) / m_resolution)),
		static_cast<int>(std::floor((y - m_y0) / m_resolution)));
	return cell < 0 ? -1.0 : static_cast<double>(m_distance[static_cast<size_t>(cell)]);
}

long CorrelationTables::cellIndex(int u, int v) const
{
	if (u < 0 || v < 0 || u >= m_width || v >= m_height) return -1;
	return static_cast<long>(v) * m_width + u;
}
}  // namespace featloc
