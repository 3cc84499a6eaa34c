// CorrelationTables::buildNear against build (OpenCV's exact distance
// transform): the same distances and table values within the distance it
// keeps (the table's exponential to float rounding), none beyond, also
// where the table's edges cut the discs, and the same branch and bound;
// the branch and bound (its bounds rounded up to bytes) against every pose
// of its window.
#include <gtest/gtest.h>
#include <mrpt/core/bits_math.h>

#include <cmath>
#include <functional>
#include <limits>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "featloc/matchers/CorrelationTables.h"

using featloc::CorrelationTables;

namespace
{
constexpr double kRes = 0.03, kHit = 0.05, kX0 = -1.0, kY0 = -2.0;
constexpr int kWidth = 220, kHeight = 160, kTop = 4;

// A room's corner, a wall with a gap and a short stub, as a scan draws them.
void draw(cv::Mat& s)
{
	cv::line(s, {20, 20}, {200, 20}, cv::Scalar(0));
	cv::line(s, {20, 20}, {20, 140}, cv::Scalar(0));
	cv::line(s, {60, 140}, {120, 140}, cv::Scalar(0));
	cv::line(s, {140, 141}, {205, 139}, cv::Scalar(0));
	cv::line(s, {100, 70}, {104, 75}, cv::Scalar(0));
}

// Walls on the table's edges and one corner.
void drawAtEdges(cv::Mat& s)
{
	cv::line(s, {0, 3}, {0, kHeight - 10}, cv::Scalar(0));
	cv::line(s, {2, kHeight - 1}, {kWidth - 1, kHeight - 1}, cv::Scalar(0));
	cv::line(s, {kWidth - 3, 0}, {kWidth - 1, 2}, cv::Scalar(0));
	cv::line(s, {50, 1}, {90, 1}, cv::Scalar(0));
}

// Near tables of the surface `drawn` against the exact ones over the whole
// table: the same distances and values within maxDistance (at least 2000
// cells), none beyond (at least 10000).
void expectNearIsExact(const std::function<void(cv::Mat&)>& drawn, double maxDistance)
{
	CorrelationTables exact, near;
	exact.build(kWidth, kHeight, kX0, kY0, kRes, kHit, kTop, drawn);
	near.buildNear(kWidth, kHeight, kX0, kY0, kRes, kHit, kTop, maxDistance, drawn);
	size_t inside = 0, beyond = 0;
	for (int v = 0; v < kHeight; v++)
		for (int u = 0; u < kWidth; u++)
		{
			const double x = kX0 + (u + 0.5) * kRes, y = kY0 + (v + 0.5) * kRes;
			const double d = exact.distanceAt(x, y);
			const std::vector<double> px{x}, py{y};
			const mrpt::poses::CPose2D origin;
			if (d <= maxDistance - kRes)
			{
				inside++;
				ASSERT_FLOAT_EQ(static_cast<float>(near.distanceAt(x, y)), static_cast<float>(d))
					<< u << ", " << v;
				// The exponential: std::exp against cv::exp, to float rounding.
				const double e = exact.score(px, py, origin);
				ASSERT_NEAR(near.score(px, py, origin), e, 1e-5 * e) << u << ", " << v;
			}
			else if (d > maxDistance + kRes)
			{
				beyond++;
				ASSERT_EQ(near.distanceAt(x, y), std::numeric_limits<double>::infinity());
				ASSERT_EQ(near.score(px, py, origin), 0.0);
				// What the exact table holds there: nothing a score can see.
				ASSERT_LT(exact.score(px, py, origin), std::exp(-0.5 * std::pow(maxDistance / kHit, 2)));
			}
		}
	EXPECT_GT(inside, 2000u);
	EXPECT_GT(beyond, 10000u);
	// Outside the table: no distance either way.
	EXPECT_LT(near.distanceAt(kX0 - 1, kY0), 0.0);
}
}  // namespace

TEST(CorrelationTables, NearTablesAreTheExactOnesWithinTheirDistance)
{
	expectNearIsExact(draw, 0.25);
}

TEST(CorrelationTables, NearTablesGiveTheSameBranchAndBound)
{
	CorrelationTables exact, near;
	exact.build(kWidth, kHeight, kX0, kY0, kRes, kHit, kTop, draw);
	near.buildNear(kWidth, kHeight, kX0, kY0, kRes, kHit, kTop, 5 * kHit, draw);
	// Points on the corner's walls and the stub, seen from a pose 8 cm, 5 cm
	// and 2 deg off the table's frame.
	const mrpt::poses::CPose2D truth(0.08, -0.05, mrpt::DEG2RAD(2.0));
	std::vector<double> px, py;
	auto add = [&](int u, int v)
	{
		double x = 0, y = 0;
		truth.inverseComposePoint(kX0 + (u + 0.5) * kRes, kY0 + (v + 0.5) * kRes, x, y);
		px.push_back(x);
		py.push_back(y);
	};
	for (int u = 30; u < 190; u += 8) add(u, 20);
	for (int v = 30; v < 130; v += 8) add(20, v);
	add(102, 72);
	CorrelationTables::Window w;
	w.nx = w.ny = 10;
	w.nYaw = 4;
	w.yawStep = CorrelationTables::rotationStep(px, py, kRes);
	const auto a = exact.search(px, py, w, 0.9), b = near.search(px, py, w, 0.9);
	ASSERT_FALSE(a.empty());
	ASSERT_EQ(a.size(), b.size());
	for (size_t i = 0; i < a.size(); i++)
	{
		EXPECT_EQ(a[i].pose.x(), b[i].pose.x());
		EXPECT_EQ(a[i].pose.y(), b[i].pose.y());
		EXPECT_EQ(a[i].pose.phi(), b[i].pose.phi());
		EXPECT_NEAR(a[i].score, b[i].score, 1e-6);
	}
	EXPECT_NEAR(a[0].pose.x(), truth.x(), kRes);
	EXPECT_NEAR(a[0].pose.y(), truth.y(), kRes);
}

TEST(CorrelationTables, NearTablesAreExactWhereTheEdgesCutTheirDiscs)
{
	expectNearIsExact(drawAtEdges, 0.25);
}

TEST(CorrelationTables, BranchAndBoundFindsEveryPoseAtOrAboveTheRatio)
{
	CorrelationTables t;
	t.buildNear(kWidth, kHeight, kX0, kY0, kRes, kHit, kTop, 5 * kHit, draw);
	// The corner's walls and the stub from 8 cm, -5 cm, 2 deg, and points
	// that some of the window's poses put off the table (left of its low
	// edge, above its high one).
	const mrpt::poses::CPose2D truth(0.08, -0.05, mrpt::DEG2RAD(2.0));
	std::vector<double> px, py;
	auto add = [&](double x, double y)
	{
		double lx = 0, ly = 0;
		truth.inverseComposePoint(x, y, lx, ly);
		px.push_back(lx);
		py.push_back(ly);
	};
	auto cell = [&](int u, int v) { add(kX0 + (u + 0.5) * kRes, kY0 + (v + 0.5) * kRes); };
	for (int u = 30; u < 190; u += 8) cell(u, 20);
	for (int v = 30; v < 130; v += 8) cell(20, v);
	for (int u = 62; u < 120; u += 9) cell(u, 140);
	cell(102, 72);
	add(kX0 + 0.1, 0.0);
	add(0.0, kY0 + kHeight * kRes - 0.1);
	CorrelationTables::Window w;
	w.nx = 12;
	w.ny = 9;
	w.nYaw = 3;
	w.yawStep = CorrelationTables::rotationStep(px, py, kRes);
	// Every pose that puts a point on a surface, with its score (a ratio
	// no pose falls below): the branch and bound must find those at or
	// above the ratio, and only those, with the same scores, in the same
	// order, whatever its bounds prune.
	const auto all = t.search(px, py, w, 1e-12);
	ASSERT_GT(all.size(), 1000u);
	for (double ratio : {1.0, 0.999, 0.995, 0.99, 0.98, 0.95, 0.9, 0.8, 0.5})
	{
		const auto kept = t.search(px, py, w, ratio);
		std::vector<CorrelationTables::Candidate> expected;
		for (const auto& c : all)
			if (c.score >= ratio * all[0].score) expected.push_back(c);
		ASSERT_EQ(kept.size(), expected.size()) << ratio;
		for (size_t i = 0; i < kept.size(); i++)
		{
			ASSERT_EQ(kept[i].score, expected[i].score) << ratio << ", " << i;
			ASSERT_EQ(kept[i].pose.x(), expected[i].pose.x()) << ratio << ", " << i;
			ASSERT_EQ(kept[i].pose.y(), expected[i].pose.y()) << ratio << ", " << i;
			ASSERT_EQ(kept[i].pose.phi(), expected[i].pose.phi()) << ratio << ", " << i;
			// The score is the pose's own, as score() computes it, to the
			// rounding of the cell a point falls in.
			ASSERT_NEAR(t.score(px, py, kept[i].pose), kept[i].score, 0.05) << ratio << ", " << i;
		}
	}
	EXPECT_NEAR(all[0].pose.x(), truth.x(), kRes);
	EXPECT_NEAR(all[0].pose.y(), truth.y(), kRes);
}
