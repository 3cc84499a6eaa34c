#include "featloc/sim/WalkingAgent.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace featloc
{
namespace
{
// [m] a person's proportions for the camera (the laser sees only 2-D).
constexpr double kHip = 0.85, kShoulder = 1.5, kHeight = 1.72;
}  // namespace

WalkingAgent::WalkingAgent(Params params) : m_params(std::move(params))
{
	const auto& w = m_params.waypoints;
	if (w.empty())
		throw std::invalid_argument("agent '" + m_params.name + "' has no waypoints");
	std::vector<mrpt::math::TPoint2D> route(w.begin(), w.end());
	if (m_params.mode == Mode::Loop && w.size() > 1) route.push_back(w.front());
	if (m_params.mode == Mode::PingPong && w.size() > 1)
		route.insert(route.end(), w.rbegin() + 1, w.rend());

	double t = 0, dist = 0;
	for (size_t i = 1; i < route.size(); i++)
	{
		const double len =
			std::hypot(route[i].x - route[i - 1].x, route[i].y - route[i - 1].y);
		if (len > 0)
		{
			m_phases.push_back(
				{t, len / m_params.speed, route[i - 1], route[i], true, dist});
			t += len / m_params.speed;
			dist += len;
		}
		if (m_params.pause > 0)
		{
			m_phases.push_back({t, m_params.pause, route[i], route[i], false, dist});
			t += m_params.pause;
		}
	}
	m_routeDuration = t;
	m_routeDistance = dist;
}

WalkingAgent::State WalkingAgent::stateAt(double tAbs) const
{
	State st;
	const auto& w = m_params.waypoints;
	st.position = w.front();
	if (w.size() > 1) st.heading = std::atan2(w[1].y - w[0].y, w[1].x - w[0].x);
	double tau = tAbs - m_params.startTime;
	if (m_phases.empty() || tau < 0) return st;

	double laps = 0;
	if (m_params.mode != Mode::Once)
	{
		laps = std::floor(tau / m_routeDuration);
		tau -= laps * m_routeDuration;
	}
	else if (tau >= m_routeDuration)  // finished: stands at the last point
	{
		st.position = m_phases.back().to;
		for (auto it = m_phases.rbegin(); it != m_phases.rend(); ++it)
			if (it->walking)
			{
				st.heading = std::atan2(it->to.y - it->from.y, it->to.x - it->from.x);
				break;
			}
		st.distance = m_routeDistance;
		return st;
	}
	const auto it = std::upper_bound(
		m_phases.begin(), m_phases.end(), tau,
		[](double v, const Phase& p) { return v < p.start; });
	const Phase& p = *std::prev(it);
	// Heading: of this walk, or of the last walk before a pause.
	const Phase* walk = &p;
	for (auto k = std::prev(it);; --k)
	{
		if (k->walking)
		{
			walk = &*k;
			break;
		}
		if (k == m_phases.begin())
		{
			walk = &m_phases.back();
			break;
		}
	}
	st.heading = std::atan2(walk->to.y - walk->from.y, walk->to.x - walk->from.x);
	const double s = std::clamp((tau - p.start) / p.duration, 0.0, 1.0);
	st.position = {p.from.x + s * (p.to.x - p.from.x), p.from.y + s * (p.to.y - p.from.y)};
	st.walking = p.walking;
	st.distance = laps * m_routeDistance + p.distanceAtStart +
		(p.walking ? s * std::hypot(p.to.x - p.from.x, p.to.y - p.from.y) : 0);
	return st;
}

void WalkingAgent::segmentsAt(double t, std::vector<WallSegment>& out) const
{
	if (m_params.shape != Shape::Cart) return;
	const State st = stateAt(t);
	const double ch = std::cos(st.heading), sh = std::sin(st.heading);
	const double l = m_params.cartLength / 2, w = m_params.cartWidth / 2;
	mrpt::math::TPoint2D corner[4];
	const double along[4] = {l, -l, -l, l}, across[4] = {w, w, -w, -w};
	for (int k = 0; k < 4; k++)
		corner[k] = {st.position.x + along[k] * ch - across[k] * sh,
			st.position.y + along[k] * sh + across[k] * ch};
	for (int k = 0; k < 4; k++)
	{
		WallSegment s;
		s.a = corner[k];
		s.b = corner[(k + 1) % 4];
		s.object = m_params.name;
		s.texture = m_params.texture;
		s.top = kHip;
		s.solid = true;
		out.push_back(s);
	}
}

void WalkingAgent::shapesAt(double t, std::vector<CircleShape>& out) const
{
	if (m_params.shape == Shape::Cart) return;
	const State st = stateAt(t);
	CircleShape c;
	c.texture = m_params.texture;
	c.object = m_params.name;
	if (m_params.shape == Shape::Body)
	{
		c.centre = st.position;
		c.radius = m_params.bodyRadius;
		c.top = kHeight;
		out.push_back(c);
		return;
	}
	// Legs: side by side across the heading, swinging along it in
	// opposition while walking (one gait cycle per strideLength).
	const double ch = std::cos(st.heading), sh = std::sin(st.heading);
	const double swing = st.walking
		? m_params.stepAmplitude *
			std::sin(2 * M_PI * st.distance / m_params.strideLength)
		: 0.0;
	for (int side : {-1, 1})
	{
		const double across = side * m_params.legSeparation / 2;
		const double along = side * swing;
		c.centre = {st.position.x + along * ch - across * sh,
			st.position.y + along * sh + across * ch};
		c.radius = m_params.legRadius;
		c.top = kHip;
		out.push_back(c);
	}
}

void WalkingAgent::cameraShapesAt(double t, std::vector<CircleShape>& out) const
{
	shapesAt(t, out);
	if (m_params.shape != Shape::Legs) return;
	const State st = stateAt(t);
	CircleShape c;
	c.texture = m_params.texture;
	c.object = m_params.name;
	c.centre = st.position;
	// Torso as wide as the legs' stance, and a head.
	c.radius = std::max(m_params.legSeparation / 2 + m_params.legRadius, 0.12);
	c.bottom = kHip;
	c.top = kShoulder;
	out.push_back(c);
	c.radius = 0.1;
	c.bottom = kShoulder;
	c.top = kHeight;
	c.texture = "plain";
	out.push_back(c);
}
}  // namespace featloc
