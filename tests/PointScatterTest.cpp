// The one total-least-squares line fit that LineFit (PCM's features),
// LineEllipseExtractor's weighted refits and ReferencePolyline (IDC's local
// lines) share.
#include <gtest/gtest.h>

#include <cmath>

#include "featloc/features/PointScatter.h"

using namespace featloc;

// Points on a line 30 deg from the x axis, 20 km from the origin, +-1 mm
// across it (symmetric along it, so that the line stays the line): the
// centroid and the normal come out exact to rounding (the sums are taken
// about the first point; raw sums of squares of 1e4 m coordinates would
// lose the millimetres), and the eigenvalue gap is the along-line spread
// less the across-line one.
TEST(PointScatter, LineFarFromTheOriginIsExact)
{
	const double a = M_PI / 6, ox = 1e4, oy = -2e4;
	const double dx = std::cos(a), dy = std::sin(a), nx = -dy, ny = dx;
	PointScatter s;
	double along2 = 0, across2 = 0;
	for (int k = 0; k < 11; k++)
	{
		const double t = 0.1 * (k - 5);
		const int d = std::abs(k - 5);
		const double e = d >= 4 ? 1e-3 : d >= 2 ? -1e-3 : 0.0;
		s.add(ox + t * dx + e * nx, oy + t * dy + e * ny);
		along2 += t * t;
		across2 += e * e;
	}
	const PointScatter::Line l = s.line();
	EXPECT_NEAR(std::abs(l.nx * nx + l.ny * ny), 1.0, 1e-12);
	EXPECT_GE(l.ny, 0.0);  // direction in (-pi/2, pi/2]
	EXPECT_NEAR(s.cx(), ox, 1e-9);
	EXPECT_NEAR(s.cy(), oy, 1e-9);
	EXPECT_NEAR(l.gap, along2 - across2, 1e-10);
	EXPECT_EQ(s.count(), 11u);

	// A vertical line's normal is (1, 0) or (-1, 0), with the direction
	// pi/2 (the half-open end of the interval).
	PointScatter v;
	for (int k = 0; k < 5; k++) v.add(3, k);
	EXPECT_NEAR(std::abs(v.line().nx), 1.0, 1e-15);
	EXPECT_NEAR(v.line().ny, 0.0, 1e-15);
}

// LineEllipseExtractor's weighted lines: a point of weight w counts as w
// copies of it, so a weight of 3 gives the fit of the point added three
// times; and a far outlier of weight 1e-9 does not tilt the line, where
// unweighted it would.
TEST(PointScatter, AWeightCountsAsThatManyCopiesOfThePoint)
{
	const double pts[][2] = {{0, 0}, {1, 0.1}, {2, 0.15}, {3, 0.35}, {4, 0.4}};
	const int copies[] = {1, 3, 2, 1, 4};
	PointScatter weighted, repeated;
	for (int k = 0; k < 5; k++)
	{
		weighted.add(pts[k][0], pts[k][1], copies[k]);
		for (int c = 0; c < copies[k]; c++) repeated.add(pts[k][0], pts[k][1]);
	}
	EXPECT_DOUBLE_EQ(weighted.weight(), 11.0);
	EXPECT_EQ(weighted.count(), 5u);
	EXPECT_NEAR(weighted.cx(), repeated.cx(), 1e-12);
	EXPECT_NEAR(weighted.cy(), repeated.cy(), 1e-12);
	EXPECT_NEAR(weighted.line().nx, repeated.line().nx, 1e-12);
	EXPECT_NEAR(weighted.line().ny, repeated.line().ny, 1e-12);
	EXPECT_NEAR(weighted.line().gap, repeated.line().gap, 1e-12);

	PointScatter light, heavy;
	for (int k = 0; k < 5; k++)
	{
		light.add(k, 0);
		heavy.add(k, 0);
	}
	light.add(2, 5, 1e-9);
	heavy.add(2, 5);
	EXPECT_NEAR(light.line().nx, 0.0, 1e-6);  // still the x axis
	EXPECT_NEAR(light.cy(), 0.0, 1e-6);
	EXPECT_GT(heavy.cy(), 0.8);	 // unweighted, the outlier pulls the centroid
}
