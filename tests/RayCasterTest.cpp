#include <gtest/gtest.h>
#include <mrpt/random/RandomGenerators.h>

#include <cmath>
#include <limits>

#include "featloc/sim/RayCaster.h"

using namespace featloc;
using mrpt::math::TPoint2D;
using mrpt::math::TPose2D;

namespace
{
const double kInf = std::numeric_limits<double>::infinity();

WallSegment seg(double x0, double y0, double x1, double y1)
{
	WallSegment s;
	s.a = {x0, y0};
	s.b = {x1, y1};
	return s;
}

CircleShape circ(double x, double y, double r)
{
	CircleShape c;
	c.centre = {x, y};
	c.radius = r;
	return c;
}

/** Independent reference: every beam against every shape, no culling. */
std::vector<double> bruteForce(
	const TPose2D& s, double first, double step, size_t n, double maxRange,
	const std::vector<WallSegment>& segs, const std::vector<CircleShape>& circles)
{
	std::vector<double> out(n, kInf);
	for (size_t i = 0; i < n; i++)
	{
		const double a = s.phi + first + step * static_cast<double>(i);
		const double dx = std::cos(a), dy = std::sin(a);
		for (const auto& g : segs)
		{
			// Solve s + t d = a + u (b - a) by Cramer's rule.
			const double m00 = dx, m01 = -(g.b.x - g.a.x), m10 = dy, m11 = -(g.b.y - g.a.y);
			const double det = m00 * m11 - m01 * m10;
			if (det == 0) continue;
			const double rx = g.a.x - s.x, ry = g.a.y - s.y;
			const double t = (rx * m11 - m01 * ry) / det;
			const double u = (m00 * ry - m10 * rx) / det;
			if (t > 0 && u >= 0 && u <= 1) out[i] = std::min(out[i], t);
		}
		for (const auto& c : circles)
		{
			const double fx = s.x - c.centre.x, fy = s.y - c.centre.y;
			if (fx * fx + fy * fy <= c.radius * c.radius) continue;
			const double b = fx * dx + fy * dy;
			const double disc = b * b - (fx * fx + fy * fy - c.radius * c.radius);
			if (disc < 0) continue;
			const double t = -b - std::sqrt(disc);
			if (t > 0) out[i] = std::min(out[i], t);
		}
		if (out[i] >= maxRange) out[i] = kInf;
	}
	return out;
}
}  // namespace

TEST(RayCaster, PerpendicularWallGivesDistanceOverCosine)
{
	// Sensor at the origin facing +x, 91 beams from -45 to +45 deg, wall x=2.
	std::vector<double> r;
	const double step = M_PI / 2 / 90;
	RayCaster::cast({0, 0, 0}, -M_PI / 4, step, 91, 30, {seg(2, -5, 2, 5)}, {}, r);
	for (size_t i = 0; i < 91; i++)
	{
		const double a = -M_PI / 4 + step * static_cast<double>(i);
		EXPECT_NEAR(r[i], 2 / std::cos(a), 1e-12) << i;
	}
}

TEST(RayCaster, HandComputedHitsMissesAndOcclusion)
{
	// Sensor at (1, 1) facing +y; beams at -90, 0, +90 deg (to +x, +y, -x).
	const TPose2D s{1, 1, M_PI / 2};
	std::vector<double> r;
	RayCaster::cast(s, -M_PI / 2, M_PI / 2, 3, 30,
		{seg(4, 0, 4, 2), seg(-1, 3, 3, 3)}, {circ(1, 2.5, 0.5)}, r);
	EXPECT_NEAR(r[0], 3.0, 1e-12);	// wall x = 4
	EXPECT_NEAR(r[1], 1.0, 1e-12);	// circle (1, 2.5) r 0.5 before the wall y = 3
	EXPECT_EQ(r[2], kInf);	// nothing to the left
	// A short segment not spanning the beam is missed.
	RayCaster::cast(s, -M_PI / 2, M_PI / 2, 3, 30, {seg(4, 1.5, 4, 2)}, {}, r);
	EXPECT_EQ(r[0], kInf);
}

TEST(RayCaster, TangentAndGrazingCircle)
{
	// Beam along +x at y = 0; circle of radius 1 centred (5, 0.6):
	// t = 5 - sqrt(1 - 0.36) = 4.2.
	std::vector<double> r;
	RayCaster::cast({0, 0, 0}, 0, 0.1, 1, 30, {}, {circ(5, 0.6, 1)}, r);
	EXPECT_NEAR(r[0], 4.2, 1e-12);
	RayCaster::cast({0, 0, 0}, 0, 0.1, 1, 30, {}, {circ(5, 1.2, 1)}, r);
	EXPECT_EQ(r[0], kInf);
}

TEST(RayCaster, MaxRangeAndSensorInsideCircle)
{
	std::vector<double> r;
	RayCaster::cast({0, 0, 0}, 0, 0.1, 1, 5, {seg(6, -1, 6, 1)}, {}, r);
	EXPECT_EQ(r[0], kInf);
	RayCaster::cast({0, 0, 0}, 0, 0.1, 1, 30, {seg(6, -1, 6, 1)}, {circ(0.1, 0, 0.5)}, r);
	EXPECT_NEAR(r[0], 6, 1e-12);  // the circle around the sensor is ignored
}

TEST(RayCaster, FullCircleFanAcrossTheAngleSeam)
{
	// 360 beams all around; a wall behind the sensor spans the -pi/+pi seam
	// of the fan's relative angle when the sensor faces +x.
	std::vector<double> r;
	const double step = 2 * M_PI / 360;
	RayCaster::cast({0, 0, 0}, -M_PI, step, 360, 30, {seg(-3, -1, -3, 1)}, {}, r);
	EXPECT_NEAR(r[0], 3.0, 1e-12);	 // angle -pi
	EXPECT_NEAR(r[5], 3 / std::cos(5 * step), 1e-12);
	EXPECT_NEAR(r[355], 3 / std::cos(5 * step), 1e-12);
	EXPECT_EQ(r[180], kInf);  // angle 0: nothing ahead
}

TEST(RayCaster, CullingMatchesBruteForceOnRandomWorlds)
{
	mrpt::random::CRandomGenerator rng(42);
	for (int trial = 0; trial < 20; trial++)
	{
		std::vector<WallSegment> segs;
		std::vector<CircleShape> circles;
		for (int i = 0; i < 60; i++)
		{
			const double x = rng.drawUniform(-10.0, 10.0), y = rng.drawUniform(-10.0, 10.0);
			const double a = rng.drawUniform(-M_PI, M_PI), l = rng.drawUniform(0.1, 4.0);
			segs.push_back(seg(x, y, x + l * std::cos(a), y + l * std::sin(a)));
		}
		for (int i = 0; i < 10; i++)
			circles.push_back(circ(rng.drawUniform(-10.0, 10.0), rng.drawUniform(-10.0, 10.0),
				rng.drawUniform(0.05, 0.8)));
		const TPose2D s{rng.drawUniform(-3.0, 3.0), rng.drawUniform(-3.0, 3.0),
			rng.drawUniform(-M_PI, M_PI)};
		const size_t n = (trial % 2) ? 1081 : 361;
		const double aperture = (trial % 2) ? 1.5 * M_PI : M_PI;
		const double step = aperture / static_cast<double>(n - 1);
		std::vector<double> fast;
		RayCaster::cast(s, -aperture / 2, step, n, 15, segs, circles, fast);
		const auto ref = bruteForce(s, -aperture / 2, step, n, 15, segs, circles);
		for (size_t i = 0; i < n; i++)
		{
			if (std::isinf(ref[i]))
				EXPECT_TRUE(std::isinf(fast[i])) << "trial " << trial << " beam " << i;
			else
				EXPECT_NEAR(fast[i], ref[i], 1e-9) << "trial " << trial << " beam " << i;
		}
	}
}
