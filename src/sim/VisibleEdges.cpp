#include "featloc/sim/VisibleEdges.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace featloc
{
namespace
{
/** Point on the object's polyline at distance s from its start. */
bool pointAt(
	const std::vector<const WallSegment*>& polyline, double s, double& x, double& y)
{
	for (const auto* sg : polyline)
	{
		const double len = std::hypot(sg->b.x - sg->a.x, sg->b.y - sg->a.y);
		if (s >= sg->sStart - 1e-9 && s <= sg->sStart + len + 1e-9)
		{
			const double l = std::clamp((s - sg->sStart) / len, 0.0, 1.0);
			x = sg->a.x + l * (sg->b.x - sg->a.x);
			y = sg->a.y + l * (sg->b.y - sg->a.y);
			return true;
		}
	}
	return false;
}

bool project(
	const StereoCameraOptions& c, const mrpt::poses::CPose3D& camera, double x, double y,
	double z, double& u, double& v, double& depth)
{
	double lx = 0, ly = 0, lz = 0;
	camera.inverseComposePoint(x, y, z, lx, ly, lz);
	if (lz <= 1e-3) return false;
	u = c.fx * lx / lz + c.cx;
	v = c.fy * ly / lz + c.cy;
	depth = lz;
	return true;
}

/** The surface at (u, v) is at `depth`: one of the pixels around the
 * projection (an edge pixel itself is mixed, its neighbours are not). */
bool seen(const cv::Mat& depthImage, double u, double v, double depth)
{
	const int r = static_cast<int>(std::lround(v));
	if (r < 0 || r >= depthImage.rows) return false;
	const int c0 = static_cast<int>(std::floor(u));
	const double tol = std::max(0.02, 0.01 * depth);
	for (int c = c0 - 1; c <= c0 + 2; c++)
	{
		if (c < 0 || c >= depthImage.cols) continue;
		const float d = depthImage.at<float>(r, c);
		if (d > 0 && std::abs(d - depth) < tol) return true;
	}
	return false;
}
}  // namespace

VisibleEdges::VisibleEdges(const SimWorld& world, const StereoCameraOptions& camera)
	: m_cam(camera)
{
	std::map<std::string, std::vector<const WallSegment*>> objects;
	std::vector<std::string> order;
	for (const auto& s : world.segments())
	{
		if (!objects.count(s.object)) order.push_back(s.object);
		objects[s.object].push_back(&s);
	}
	for (const auto& name : order)
	{
		const auto& poly = objects[name];
		const bool closedLoop = poly.size() > 1 &&
			std::hypot(poly.front()->a.x - poly.back()->b.x, poly.front()->a.y - poly.back()->b.y) < 1e-9;
		// Ends and corners: a joint where the direction does not change
		// (a straight polyline through a point) is no edge.
		for (size_t i = 0; i <= poly.size(); i++)
		{
			const WallSegment* before = i > 0 ? poly[i - 1] : nullptr;
			const WallSegment* after = i < poly.size() ? poly[i] : nullptr;
			if (closedLoop && i == poly.size()) break;	// the first point again
			if (closedLoop && i == 0) before = poly.back();
			if (before && after)
			{
				const double a1 = std::atan2(before->b.y - before->a.y, before->b.x - before->a.x);
				const double a2 = std::atan2(after->b.y - after->a.y, after->b.x - after->a.x);
				if (std::abs(std::remainder(a2 - a1, 2 * M_PI)) < 1e-2) continue;
			}
			const WallSegment* sg = after ? after : before;
			const auto p = after ? after->a : before->b;
			m_edges.push_back({p.x, p.y, sg->bottom, sg->top, name, after ? after->sStart : before->sStart + std::hypot(before->b.x - before->a.x, before->b.y - before->a.y)});
		}
		for (const auto& patch : poly.front()->patches)
			for (double s : {patch.s0, patch.s1})
			{
				WorldEdge e;
				if (!pointAt(poly, s, e.x, e.y)) continue;
				e.zLow = patch.z0;
				e.zHigh = patch.z1;
				e.object = name;
				e.s = s;
				m_edges.push_back(e);
			}
	}
}

std::vector<VisibleEdge> VisibleEdges::visible(
	const mrpt::poses::CPose3D& left, const cv::Mat& leftDepth, const cv::Mat& rightDepth) const
{
	const mrpt::poses::CPose3D right = left + mrpt::poses::CPose3D(m_cam.baseline, 0, 0, 0, 0, 0);
	std::vector<VisibleEdge> out;
	for (const auto& e : m_edges)
	{
		double u = 0, v = 0, depth = 0;
		if (!project(m_cam, left, e.x, e.y, 0.5 * (e.zLow + e.zHigh), u, v, depth)) continue;
		// About one sample per image row along the edge.
		const double dz = std::max(depth / m_cam.fy, 1e-3);
		const int n = std::max(2, static_cast<int>((e.zHigh - e.zLow) / dz));
		double lo = 1e300, hi = -1e300;
		int seenLeft = 0, seenRight = 0;
		for (int k = 0; k <= n; k++)
		{
			// Stay a hair inside the ends (the end rows are mixed pixels).
			const double z = e.zLow + (e.zHigh - e.zLow) * (0.002 + 0.996 * k / n);
			if (!project(m_cam, left, e.x, e.y, z, u, v, depth)) continue;
			if (u < 0 || u > m_cam.width - 1 || v < 0 || v > m_cam.height - 1) continue;
			if (!seen(leftDepth, u, v, depth)) continue;
			seenLeft++;
			lo = std::min(lo, z);
			hi = std::max(hi, z);
			double ur = 0, vr = 0, dr = 0;
			if (project(m_cam, right, e.x, e.y, z, ur, vr, dr) && ur >= 0 &&
				ur <= m_cam.width - 1 && seen(rightDepth, ur, vr, dr))
				seenRight++;
		}
		if (seenLeft < 3) continue;
		VisibleEdge ve;
		ve.edge = e;
		ve.zLow = lo;
		ve.zHigh = hi;
		double d = 0;
		project(m_cam, left, e.x, e.y, lo, ve.uLeftLow, ve.vLeftLow, d);
		project(m_cam, left, e.x, e.y, hi, ve.uLeftHigh, ve.vLeftHigh, d);
		project(m_cam, right, e.x, e.y, lo, ve.uRightLow, ve.vRightLow, d);
		project(m_cam, right, e.x, e.y, hi, ve.uRightHigh, ve.vRightHigh, d);
		ve.visibleRight = seenRight * 2 > seenLeft;
		out.push_back(ve);
	}
	return out;
}
}  // namespace featloc
