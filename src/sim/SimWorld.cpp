#include "featloc/sim/SimWorld.h"

#include <mrpt/core/bits_math.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "featloc/config/ConfigValues.h"
#include "featloc/core/ConfigError.h"

namespace featloc
{
namespace
{
using mrpt::math::TPoint2D;

bool hasPrefix(const std::string& s, const std::string& prefix)
{
	if (s.size() <= prefix.size()) return false;
	for (size_t i = 0; i < prefix.size(); i++)
		if (std::tolower(static_cast<unsigned char>(s[i])) !=
			std::tolower(static_cast<unsigned char>(prefix[i])))
			return false;
	return true;
}

std::vector<TPoint2D> points(const std::vector<std::vector<double>>& rows)
{
	std::vector<TPoint2D> out;
	for (const auto& r : rows) out.emplace_back(r[0], r[1]);
	return out;
}

double pointSegmentDistance(const TPoint2D& p, const TPoint2D& a, const TPoint2D& b)
{
	const double ex = b.x - a.x, ey = b.y - a.y;
	const double len2 = ex * ex + ey * ey;
	double s = len2 > 0 ? ((p.x - a.x) * ex + (p.y - a.y) * ey) / len2 : 0;
	s = std::clamp(s, 0.0, 1.0);
	return std::hypot(p.x - (a.x + s * ex), p.y - (a.y + s * ey));
}

bool segmentsIntersect(
	const TPoint2D& a, const TPoint2D& b, const TPoint2D& c, const TPoint2D& d)
{
	auto cross = [](const TPoint2D& o, const TPoint2D& p, const TPoint2D& q) {
		return (p.x - o.x) * (q.y - o.y) - (p.y - o.y) * (q.x - o.x);
	};
	const double d1 = cross(c, d, a), d2 = cross(c, d, b);
	const double d3 = cross(a, b, c), d4 = cross(a, b, d);
	return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0));
}

double segmentSegmentDistance(
	const TPoint2D& a, const TPoint2D& b, const TPoint2D& c, const TPoint2D& d)
{
	if (segmentsIntersect(a, b, c, d)) return 0;
	return std::min(
		{pointSegmentDistance(a, c, d), pointSegmentDistance(b, c, d),
		 pointSegmentDistance(c, a, b), pointSegmentDistance(d, a, b)});
}

void loadWall(SimWorld& w, const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	std::vector<std::vector<double>> rows, posters, patches, doors;
	bool closed = false;
	std::string texture = "plain", patchTexture = "paper";
	double bottom = 0, top = 2.5;
	config::readRows(c, s, "polyline", rows, {2});
	config::read(c, s, "closed", closed);
	config::read(c, s, "texture", texture);
	config::read(c, s, "bottom", bottom);
	config::read(c, s, "height", top);
	config::readRows(c, s, "posters", posters, {4});
	config::readRows(c, s, "patches", patches, {4, 5});
	config::read(c, s, "patch_texture", patchTexture);
	// One name, or a list "[paper metal]" that a 5th column picks from.
	std::vector<std::string> patchTextures;
	{
		std::string word;
		for (char ch : patchTexture + " ")
		{
			if (std::isspace(static_cast<unsigned char>(ch)) || ch == ',' || ch == '[' || ch == ']')
			{
				if (!word.empty()) patchTextures.push_back(word);
				word.clear();
			}
			else
				word += ch;
		}
		config::require(!patchTextures.empty(), c, s, "patch_texture", "a material name or [name name ...]");
	}
	config::readRows(c, s, "doors", doors, {2});
	config::require(rows.size() >= 2, c, s, "polyline", "at least two points [x y; x y]");
	config::require(bottom >= 0, c, s, "bottom", ">= 0 [m]");
	config::require(top > bottom, c, s, "height", "above 'bottom' [m]");
	auto pts = points(rows);
	if (closed) pts.push_back(pts.front());
	double length = 0;
	for (size_t i = 1; i < pts.size(); i++)
		length += std::hypot(pts[i].x - pts[i - 1].x, pts[i].y - pts[i - 1].y);

	std::vector<SurfacePatch> all;
	auto addPatches = [&](const std::vector<std::vector<double>>& list, const char* key,
						  const std::string& fixedTexture) {
		for (const auto& r : list)
		{
			std::string tex = fixedTexture;
			if (tex.empty())
			{
				const double k = r.size() == 5 ? r[4] : 0;
				config::require(
					k >= 0 && k == std::floor(k) && k < static_cast<double>(patchTextures.size()), c,
					s, key, "a 5th column that indexes patch_texture (0.." +
						std::to_string(patchTextures.size() - 1) + ")");
				tex = patchTextures[static_cast<size_t>(k)];
			}
			config::require(
				r[0] < r[1] && r[2] < r[3] && r[0] >= -1e-9 && r[1] <= length + 1e-9 &&
					r[2] >= bottom - 1e-9 && r[3] <= top + 1e-9,
				c, s, key,
				"rows [s0 s1 z0 z1] with s0 < s1 within the polyline (0.." +
					std::to_string(length) + " m) and z0 < z1 within bottom..height");
			all.push_back({r[0], r[1], r[2], r[3], tex});
		}
	};
	// Drawn in this order, later on top: patches, posters, doors.
	addPatches(patches, "patches", "");
	addPatches(posters, "posters", "poster");
	for (const auto& d : doors)
	{
		// A closed door: the leaf, then a frame 5 cm wide around it.
		const double frame = 0.05, doorTop = std::min(2.05, top - frame);
		config::require(
			d[0] - frame >= -1e-9 && d[0] < d[1] && d[1] + frame <= length + 1e-9 &&
				bottom == 0 && doorTop > 0.5,
			c, s, "doors",
			"rows [s0 s1] with a 5 cm frame on both sides inside the polyline, on a wall "
			"standing on the floor and at least 2.1 m high");
		all.push_back({d[0], d[1], 0, doorTop, "wood"});
		all.push_back({d[0] - frame, d[0], 0, doorTop + frame, "door_frame"});
		all.push_back({d[1], d[1] + frame, 0, doorTop + frame, "door_frame"});
		all.push_back({d[0], d[1], doorTop, doorTop + frame, "door_frame"});
	}
	double sAt = 0;
	for (size_t i = 1; i < pts.size(); i++)
	{
		WallSegment seg{pts[i - 1], pts[i], texture, s, bottom, top, sAt, all};
		sAt += std::hypot(pts[i].x - pts[i - 1].x, pts[i].y - pts[i - 1].y);
		w.addSegment(seg);
	}
}

void loadObstacle(
	SimWorld& w, const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	std::vector<std::vector<double>> polygon, circle;
	std::string texture = "plain";
	config::readRows(c, s, "polygon", polygon, {2});
	config::readRows(c, s, "circle", circle, {3});
	config::read(c, s, "texture", texture);
	// Desks and cabinets are furniture height; a pillar or bin 1 m.
	double top = circle.empty() ? 0.75 : 1.0;
	config::read(c, s, "height", top);
	config::require(top > 0, c, s, "height", "> 0 [m]");
	if (polygon.empty() == circle.empty())
		config::fail(c, s, "polygon",
			"an obstacle needs either 'polygon = [x y; ...]' or "
			"'circle = [cx cy r]', not both or none");
	if (!circle.empty())
	{
		config::require(circle.size() == 1 && circle[0][2] > 0, c, s, "circle",
			"one row [cx cy r] with r > 0");
		w.addCircle({TPoint2D(circle[0][0], circle[0][1]), circle[0][2], texture, s, 0, top});
		return;
	}
	config::require(polygon.size() >= 3, c, s, "polygon", "at least three points");
	auto pts = points(polygon);
	pts.push_back(pts.front());
	double sAt = 0;
	for (size_t i = 1; i < pts.size(); i++)
	{
		w.addSegment({pts[i - 1], pts[i], texture, s, 0, top, sAt, {}, true});
		sAt += std::hypot(pts[i].x - pts[i - 1].x, pts[i].y - pts[i - 1].y);
	}
}

void loadAgent(SimWorld& w, const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	WalkingAgent::Params p;
	p.name = s;
	std::string shape = "legs", mode = "loop";
	std::vector<std::vector<double>> rows;
	std::vector<double> cartSize = {p.cartLength, p.cartWidth};
	config::readChoice(c, s, "shape", shape, {"legs", "body", "cart"});
	config::read(c, s, "cart_size", cartSize);
	config::require(cartSize.size() == 2 && cartSize[0] > 0 && cartSize[1] > 0, c, s, "cart_size",
		"[length width], both > 0");
	p.cartLength = cartSize[0];
	p.cartWidth = cartSize[1];
	config::readRows(c, s, "waypoints", rows, {2});
	config::read(c, s, "speed", p.speed);
	config::read(c, s, "pause", p.pause);
	config::readChoice(c, s, "mode", mode, {"loop", "pingpong", "once"});
	config::read(c, s, "start_time", p.startTime);
	config::read(c, s, "body_radius", p.bodyRadius);
	config::read(c, s, "leg_radius", p.legRadius);
	config::read(c, s, "leg_separation", p.legSeparation);
	config::read(c, s, "stride_length", p.strideLength);
	config::read(c, s, "step_amplitude", p.stepAmplitude);
	config::read(c, s, "texture", p.texture);
	config::require(!rows.empty(), c, s, "waypoints", "at least one point [x y; ...]");
	config::require(p.speed > 0, c, s, "speed", "> 0");
	config::require(p.pause >= 0, c, s, "pause", ">= 0");
	config::require(p.bodyRadius > 0, c, s, "body_radius", "> 0");
	config::require(p.legRadius > 0, c, s, "leg_radius", "> 0");
	config::require(p.strideLength > 0, c, s, "stride_length", "> 0");
	p.shape = shape == "body" ? WalkingAgent::Shape::Body
		: shape == "cart"	  ? WalkingAgent::Shape::Cart
							  : WalkingAgent::Shape::Legs;
	p.mode = mode == "once" ? WalkingAgent::Mode::Once
		: mode == "pingpong" ? WalkingAgent::Mode::PingPong
							 : WalkingAgent::Mode::Loop;
	p.waypoints = points(rows);
	w.addAgent(p);
}

void loadDoor(SimWorld& w, const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	SwingingDoor::Params p;
	p.name = s;
	std::vector<double> hinge;
	std::vector<std::vector<double>> rows;
	config::read(c, s, "hinge", hinge);
	config::read(c, s, "length", p.length);
	config::readRows(c, s, "swing", rows, {2});
	config::read(c, s, "period", p.period);
	config::require(hinge.size() == 2, c, s, "hinge", "[x y]");
	config::require(p.period >= 0, c, s, "period", ">= 0 (0: no repeat)");
	config::require(p.length > 0, c, s, "length", "> 0");
	config::require(!rows.empty(), c, s, "swing", "at least one keyframe [t angle_deg; ...]");
	for (size_t i = 0; i < rows.size(); i++)
	{
		config::require(i == 0 || rows[i][0] > rows[i - 1][0], c, s, "swing",
			"keyframes with increasing times [t angle_deg; ...]");
		p.swing.emplace_back(rows[i][0], mrpt::DEG2RAD(rows[i][1]));
	}
	config::require(p.period == 0 || (rows.front()[0] >= 0 && rows.back()[0] < p.period), c, s,
		"swing", "keyframe times in [0, period)");
	p.hinge = {hinge[0], hinge[1]};
	w.addDoor(p);
}
}  // namespace

SimWorld SimWorld::fromConfig(const mrpt::config::CConfigFileBase& cfg)
{
	SimWorld w;
	std::vector<std::string> sections;
	cfg.getAllSections(sections);
	for (const auto& s : sections)
	{
		if (hasPrefix(s, "Wall."))
			loadWall(w, cfg, s);
		else if (hasPrefix(s, "Obstacle."))
			loadObstacle(w, cfg, s);
		else if (hasPrefix(s, "Agent."))
			loadAgent(w, cfg, s);
		else if (hasPrefix(s, "Door."))
			loadDoor(w, cfg, s);
	}
	if (w.m_segments.empty() && w.m_circles.empty())
		throw ConfigError(
			"the world has no walls or obstacles: add [Wall.<name>] or "
			"[Obstacle.<name>] sections");
	return w;
}

SimWorld SimWorld::frozen() const
{
	SimWorld w;
	w.m_segments = m_segments;
	w.m_circles = m_circles;
	for (const auto& d : m_doors)
	{
		SwingingDoor::Params p = d.params();
		p.swing = {{0.0, d.angleAt(0)}};
		p.period = 0;
		w.m_doors.emplace_back(p);
	}
	return w;
}

const std::vector<WallSegment>& SimWorld::segmentsAt(
	double t, std::vector<WallSegment>& scratch) const
{
	const bool carts = std::any_of(m_agents.begin(), m_agents.end(),
		[](const WalkingAgent& a) { return a.params().shape == WalkingAgent::Shape::Cart; });
	if (m_doors.empty() && !carts) return m_segments;
	scratch = m_segments;
	for (const auto& d : m_doors) scratch.push_back(d.segmentAt(t));
	for (const auto& a : m_agents) a.segmentsAt(t, scratch);
	return scratch;
}

void SimWorld::circlesAt(double t, std::vector<CircleShape>& out) const
{
	out = m_circles;
	for (const auto& a : m_agents) a.shapesAt(t, out);
}

void SimWorld::cameraCirclesAt(double t, std::vector<CircleShape>& out) const
{
	out = m_circles;
	for (const auto& a : m_agents) a.cameraShapesAt(t, out);
}

double SimWorld::clearance(const TPoint2D& p) const
{
	double best = std::numeric_limits<double>::infinity();
	for (const auto& s : m_segments)
		best = std::min(best, pointSegmentDistance(p, s.a, s.b));
	for (const auto& c : m_circles)
		best = std::min(best, std::hypot(p.x - c.centre.x, p.y - c.centre.y) - c.radius);
	return best;
}

std::vector<double> SimWorld::distancesToSurfaces(
	const std::vector<TPoint2D>& points, double t) const
{
	std::vector<WallSegment> scratch;
	const auto& segments = segmentsAt(t, scratch);
	std::vector<CircleShape> circles;
	circlesAt(t, circles);
	std::vector<double> out;
	out.reserve(points.size());
	for (const auto& p : points)
	{
		double best = std::numeric_limits<double>::infinity();
		for (const auto& s : segments) best = std::min(best, pointSegmentDistance(p, s.a, s.b));
		for (const auto& c : circles)
			best = std::min(best, std::abs(std::hypot(p.x - c.centre.x, p.y - c.centre.y) - c.radius));
		out.push_back(best);
	}
	return out;
}

void SimWorld::castScan(double t, const mrpt::poses::CPose2D& sensor,
	const mrpt::obs::CObservation2DRangeScan& scan, std::vector<double>& ranges,
	std::vector<RayCaster::Hit>* hits) const
{
	const size_t n = scan.getScanSize();
	ranges.clear();
	if (n < 2) return;
	std::vector<CircleShape> circles;
	circlesAt(t, circles);
	std::vector<WallSegment> scratch;
	RayCaster::cast(sensor.asTPose(), -scan.aperture / 2.0, scan.aperture / static_cast<double>(n - 1),
		n, scan.maxRange, segmentsAt(t, scratch), circles, ranges, hits);
}

bool SimWorld::pathIsClear(const TPoint2D& a, const TPoint2D& b, double clearance) const
{
	for (const auto& s : m_segments)
		if (segmentSegmentDistance(a, b, s.a, s.b) < clearance) return false;
	for (const auto& c : m_circles)
		if (pointSegmentDistance(c.centre, a, b) < clearance + c.radius) return false;
	return true;
}

std::pair<TPoint2D, TPoint2D> SimWorld::bounds() const
{
	TPoint2D lo(1e300, 1e300), hi(-1e300, -1e300);
	auto grow = [&](double x, double y) {
		lo.x = std::min(lo.x, x);
		lo.y = std::min(lo.y, y);
		hi.x = std::max(hi.x, x);
		hi.y = std::max(hi.y, y);
	};
	for (const auto& s : m_segments)
	{
		grow(s.a.x, s.a.y);
		grow(s.b.x, s.b.y);
	}
	for (const auto& c : m_circles)
	{
		grow(c.centre.x - c.radius, c.centre.y - c.radius);
		grow(c.centre.x + c.radius, c.centre.y + c.radius);
	}
	return {lo, hi};
}
}  // namespace featloc
