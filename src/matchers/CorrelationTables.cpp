#include "featloc/matchers/CorrelationTables.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <limits>
#include <queue>

namespace featloc
{
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
	cv::Mat table(m_height, m_width, CV_32F, m_levels[0].data());
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
	// what that distance puts in the tables (the same expressions as build).
	const int R = static_cast<int>(std::floor(maxDistance / res));
	const double k = -0.5 * (res / hitSigma) * (res / hitSigma);
	struct Offset
	{
		int du, dv;
		float metres, value;
	};
	std::vector<Offset> near;
	for (int dv = -R; dv <= R; dv++)
		for (int du = -R; du <= R; du++)
			if (du * du + dv * dv <= R * R)
			{
				const float d = std::sqrt(static_cast<float>(du * du + dv * dv));
				near.push_back({du, dv, static_cast<float>(d * res), std::exp(static_cast<float>(d * d * k))});
			}
	std::fill(m_distance.begin(), m_distance.end(), std::numeric_limits<float>::infinity());
	auto& table = m_levels[0];
	std::fill(table.begin(), table.end(), 0.0f);
	for (int v = 0; v < m_height; v++)
	{
		const uint8_t* row = surface.ptr<uint8_t>(v);
		for (int u = 0; u < m_width; u++)
		{
			if (row[u] != 0) continue;
			for (const auto& o : near)
			{
				const long c = cellIndex(u + o.du, v + o.dv);
				if (c < 0 || o.metres >= m_distance[static_cast<size_t>(c)]) continue;
				m_distance[static_cast<size_t>(c)] = o.metres;
				table[static_cast<size_t>(c)] = o.value;
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
	m_levels.resize(static_cast<size_t>(m_top) + 1);
	for (auto& t : m_levels) t.resize(cells);  // every cell is written by the build
	return surface;
}

void CorrelationTables::buildLevels()
{
	// Level L + 1 is the maximum of four shifted level-L views: one pass per
	// level (the tables of a real log's scan are millions of cells, and a
	// copy and three in-place maxima read and wrote each of them 11 times).
	// Cells within 2^L of the high edges keep level L's value.
	const size_t W = static_cast<size_t>(m_width);
	for (int L = 0; L < m_top; L++)
	{
		const size_t sft = size_t{1} << L;
		const float* src = m_levels[static_cast<size_t>(L)].data();
		float* dst = m_levels[static_cast<size_t>(L) + 1].data();
		for (size_t v = 0; v < static_cast<size_t>(m_height); v++)
		{
			const float* a = src + v * W;
			float* out = dst + v * W;
			if (v + sft >= static_cast<size_t>(m_height) || sft >= W)
			{
				std::copy(a, a + W, out);
				continue;
			}
			const float* b = a + sft * W;
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
	// Mean table value under rotation w's points moved by (dx, dy) cells:
	// at level L, a bound for the block of 2^L x 2^L translations from there.
	auto score = [&](int level, int w, int dx, int dy) {
		const auto& t = m_levels[static_cast<size_t>(level)];
		double sum = 0;
		const size_t base = static_cast<size_t>(w) * n;
		for (size_t i = 0; i < n; i++)
		{
			const long c = cellIndex(cu[base + i] + dx, cv[base + i] + dy);
			if (c >= 0) sum += t[static_cast<size_t>(c)];
		}
		return sum / static_cast<double>(n);
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
	std::sort(found.begin(), found.end(),
		[](const Candidate& a, const Candidate& c) { return a.score > c.score; });
	return found;
}

double CorrelationTables::score(const std::vector<double>& px, const std::vector<double>& py,
	const mrpt::poses::CPose2D& pose) const
{
	if (px.empty() || m_levels.empty()) return 0;
	const double c = std::cos(pose.phi()), s = std::sin(pose.phi());
	const auto& t = m_levels[0];
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
