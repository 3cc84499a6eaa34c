#include <gtest/gtest.h>
#include <mrpt/core/bits_math.h>
#include <mrpt/random/RandomGenerators.h>

#include <Eigen/Dense>
#include <cmath>
#include <vector>

#include "featloc/features/CircleFit.h"

using namespace featloc;

namespace
{
/** The points a laser at the origin gets of a circle (its near side),
 * one beam every `step` rad, each range with Gaussian noise `sigma`. */
std::vector<ScanPoint> arcSeen(double ox, double oy, double r, double step, double sigma,
	mrpt::random::CRandomGenerator& rng)
{
	std::vector<ScanPoint> pts;
	const double d = std::hypot(ox, oy), centre = std::atan2(oy, ox), half = std::asin(r / d);
	for (double b = centre - half + step / 2; b < centre + half; b += step)
	{
		// The beam's nearer crossing of the circle.
		const double ux = std::cos(b), uy = std::sin(b);
		const double along = ux * ox + uy * oy, across2 = d * d - along * along;
		if (across2 > r * r) continue;
		ScanPoint p;
		p.range = along - std::sqrt(r * r - across2) + sigma * rng.drawGaussian1D_normalized();
		p.bearing = b;
		p.x = p.range * ux;
		p.y = p.range * uy;
		pts.push_back(p);
	}
	return pts;
}
}  // namespace

// A trunk of 15 cm radius 3 m away in a SICK's 0.5-degree beams: 11
// points on its near side. The fit finds the centre, its sensitivity to
// each range gives the spread of the centre over noisy scans (within the
// Monte Carlo's error and the linearisation's), and s^2 (A^T A)^-1 bounds
// that spread from above.
TEST(CircleFit, ATrunksArcGivesItsCentreAndItsSpread)
{
	mrpt::random::CRandomGenerator rng(3);
	const double ox = 2.9, oy = 0.8, r = 0.15, sigma = 0.01;
	CircleFit exact;
	const auto clean = arcSeen(ox, oy, r, mrpt::DEG2RAD(0.5), 0, rng);
	ASSERT_GE(clean.size(), 9u);
	ASSERT_TRUE(CircleFit::fit(clean.data(), clean.size(), 1.0, exact));
	EXPECT_NEAR(exact.ox, ox, 1e-9);
	EXPECT_NEAR(exact.oy, oy, 1e-9);
	EXPECT_NEAR(exact.r, r, 1e-9);
	EXPECT_NEAR(exact.sumSquares, 0, 1e-15);

	const int trials = 2000;
	Eigen::Vector2d mean = Eigen::Vector2d::Zero();
	Eigen::Matrix2d scatter = Eigen::Matrix2d::Zero();
	Eigen::Matrix2d predicted = Eigen::Matrix2d::Zero(), bound = Eigen::Matrix2d::Zero();
	int fitted = 0;
	for (int t = 0; t < trials; t++)
	{
		const auto pts = arcSeen(ox, oy, r, mrpt::DEG2RAD(0.5), sigma, rng);
		CircleFit f;
		if (!CircleFit::fit(pts.data(), pts.size(), 1.0, f)) continue;
		const Eigen::Vector2d c(f.ox - ox, f.oy - oy);
		mean += c;
		scatter += c * c.transpose();
		// Range noise moves each point along its beam u_j, and the circle
		// by d(ox, oy, r)/dz_j = -(A^T A)^-1 a_j (n_j.u_j): what
		// PointToLineCovariance takes; s^2 (A^T A)^-1 (noise along each
		// normal) bounds it from above.
		Eigen::Matrix3d bySensitivity = Eigen::Matrix3d::Zero();
		for (const auto& p : pts)
		{
			const double dx = p.x - f.ox, dy = p.y - f.oy, d = std::hypot(dx, dy);
			const Eigen::Vector3d a(-dx / d, -dy / d, -1);
			const Eigen::Vector3d dTheta =
				-f.normalInverse * a * ((dx * p.x + dy * p.y) / (d * p.range));
			bySensitivity += dTheta * dTheta.transpose();
		}
		predicted += sigma * sigma * bySensitivity.topLeftCorner<2, 2>();
		bound += sigma * sigma * f.normalInverse.topLeftCorner<2, 2>();
		fitted++;
	}
	ASSERT_GT(fitted, trials * 0.99);
	mean /= fitted;
	scatter = scatter / fitted - mean * mean.transpose();
	predicted /= fitted;
	bound /= fitted;
	// Across the line of sight and along it (the radius trades off with
	// the centre along it: its sigma is several times the other).
	const Eigen::Vector2d u = Eigen::Vector2d(ox, oy).normalized(), v(-u.y(), u.x());
	for (const Eigen::Vector2d& w : {u, v})
	{
		const double measured = w.dot(scatter * w), model = w.dot(predicted * w);
		EXPECT_GT(measured / model, 0.8) << w.transpose();
		EXPECT_LT(measured / model, 1.25) << w.transpose();
		EXPECT_GE(w.dot(bound * w), model) << w.transpose();
	}
	// A bias of the centre well inside its spread.
	EXPECT_LT(std::abs(v.dot(mean)), 0.2 * std::sqrt(v.dot(scatter * v)));
}

TEST(CircleFit, StraightOrTooFewPointsFixNoCircle)
{
	std::vector<ScanPoint> line;
	for (int k = 0; k < 10; k++)
	{
		ScanPoint p;
		p.x = 2.0;
		p.y = -0.2 + 0.04 * k;
		p.range = std::hypot(p.x, p.y);
		p.bearing = std::atan2(p.y, p.x);
		line.push_back(p);
	}
	CircleFit f;
	EXPECT_FALSE(CircleFit::fit(line.data(), line.size(), 1.0, f));
	EXPECT_FALSE(CircleFit::fit(line.data(), 2, 1.0, f));
	// Bent by 1 mm in the middle: a circle of radius about 5 m, beyond 1 m.
	line[5].x += 0.001;
	EXPECT_FALSE(CircleFit::fit(line.data(), line.size(), 1.0, f));
}
