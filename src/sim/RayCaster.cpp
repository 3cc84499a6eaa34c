#include "featloc/sim/RayCaster.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace featloc
{
namespace
{
constexpr double kTwoPi = 2 * M_PI;

/** Angle in [0, 2pi). */
double wrap0To2Pi(double a)
{
	a = std::fmod(a, kTwoPi);
	return a < 0 ? a + kTwoPi : a;
}

/** Calls f(i) for every beam index whose relative angle i*step lies in the
 * interval [lo, hi] (relative angles in [0, 2pi), hi - lo < pi, or the
 * interval wraps through 0 when hi < lo), with one beam of margin on each
 * side (the exact hit test rejects the misses). */
template <typename F>
void forBeamsIn(double lo, double hi, double step, size_t beams, F&& f)
{
	const long n = static_cast<long>(beams);
	auto range = [&](double a, double b) {
		long i0 = static_cast<long>(std::floor(a / step)) - 1;
		long i1 = static_cast<long>(std::ceil(b / step)) + 1;
		i0 = std::max(i0, 0L);
		i1 = std::min(i1, n - 1);
		for (long i = i0; i <= i1; i++) f(static_cast<size_t>(i));
	};
	if (lo <= hi)
		range(lo, hi);
	else
	{
		range(lo, kTwoPi);
		range(0, hi);
	}
}
}  // namespace

void RayCaster::cast(
	const mrpt::math::TPose2D& sensor, double firstAngle, double step,
	size_t beams, double maxRange, const std::vector<WallSegment>& segments,
	const std::vector<CircleShape>& circles, std::vector<double>& ranges,
	std::vector<Hit>* hits)
{
	const double inf = std::numeric_limits<double>::infinity();
	ranges.assign(beams, inf);
	if (hits) hits->assign(beams, Hit());
	std::vector<double> dx(beams), dy(beams);
	const double base = sensor.phi + firstAngle;
	for (size_t i = 0; i < beams; i++)
	{
		const double a = base + step * static_cast<double>(i);
		dx[i] = std::cos(a);
		dy[i] = std::sin(a);
	}
	auto relAngle = [&](double px, double py) {
		return wrap0To2Pi(std::atan2(py - sensor.y, px - sensor.x) - base);
	};

	for (size_t k = 0; k < segments.size(); k++)
	{
		const auto& s = segments[k];
		const double ex = s.b.x - s.a.x, ey = s.b.y - s.a.y;
		const double wx = s.a.x - sensor.x, wy = s.a.y - sensor.y;
		double u0 = relAngle(s.a.x, s.a.y), u1 = relAngle(s.b.x, s.b.y);
		double lo = std::min(u0, u1), hi = std::max(u0, u1);
		if (hi - lo > M_PI) std::swap(lo, hi);	// seen across angle 0
		forBeamsIn(lo, hi, step, beams, [&](size_t i) {
			// sensor + t d = a + u e  (2-D cross products)
			const double den = dx[i] * ey - dy[i] * ex;
			if (den == 0) return;
			const double t = (wx * ey - wy * ex) / den;
			const double u = (wx * dy[i] - wy * dx[i]) / den;
			if (t > 0 && u >= 0 && u <= 1 && t < ranges[i])
			{
				ranges[i] = t;
				if (hits) (*hits)[i] = {false, k, std::atan2(ex, -ey)};
			}
		});
	}

	for (size_t k = 0; k < circles.size(); k++)
	{
		const auto& c = circles[k];
		const double cx = c.centre.x - sensor.x, cy = c.centre.y - sensor.y;
		const double d2 = cx * cx + cy * cy, r2 = c.radius * c.radius;
		if (d2 <= r2) continue;	 // the sensor is inside
		const double centre = relAngle(c.centre.x, c.centre.y);
		const double half = std::asin(std::min(1.0, c.radius / std::sqrt(d2)));
		const double lo = wrap0To2Pi(centre - half), hi = wrap0To2Pi(centre + half);
		forBeamsIn(lo, hi, step, beams, [&](size_t i) {
			const double b = dx[i] * cx + dy[i] * cy;
			const double disc = b * b - (d2 - r2);
			if (disc < 0) return;
			const double t = b - std::sqrt(disc);
			if (t > 0 && t < ranges[i])
			{
				ranges[i] = t;
				// The normal at the hit: from the centre through it.
				if (hits)
					(*hits)[i] = {true, k, std::atan2(t * dy[i] - cy, t * dx[i] - cx)};
			}
		});
	}

	for (auto& r : ranges)
		if (r >= maxRange) r = inf;
}
}  // namespace featloc
