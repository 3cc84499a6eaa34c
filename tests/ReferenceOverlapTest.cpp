// ReferenceOverlap: the share of a scan's points within a distance of the
// reference, looked up by bearing instead of a k-d tree.
#include <gtest/gtest.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/random/RandomGenerators.h>
#include <mrpt/serialization/CArchive.h>

#include <string>

#include "featloc/matchers/ReferenceOverlap.h"
#include "support/SyntheticRoom.h"

using namespace featloc;
using featloc::test::SyntheticRoom;
using mrpt::poses::CPose2D;

namespace
{
/** The same share with MRPT's k-d tree: every current point's nearest
 * reference point. */
double shareByKdTree(const ScanPoints& reference, const ScanPoints& current, const CPose2D& pose,
	double distance)
{
	mrpt::maps::CSimplePointsMap map;
	for (const auto& p : reference.points) map.insertPoint(p.x, p.y, 0);
	size_t near = 0;
	for (const auto& p : current.points)
	{
		double x = 0, y = 0;
		pose.composePoint(p.x, p.y, x, y);
		float rx = 0, ry = 0, d2 = 0;
		map.kdTreeClosestPoint2D(static_cast<float>(x), static_cast<float>(y), rx, ry, d2);
		// The k-d tree works in floats: leave out points on the boundary.
		near += d2 <= distance * distance;
	}
	return static_cast<double>(near) / static_cast<double>(current.size());
}

void expectSameAsKdTree(const ScanPoints& ref, const ScanPoints& cur, const std::string& what)
{
	mrpt::random::CRandomGenerator rng(11);
	for (int k = 0; k < 200; k++)
	{
		const CPose2D pose(rng.drawUniform(-0.5, 0.5), rng.drawUniform(-0.5, 0.5),
			mrpt::DEG2RAD(rng.drawUniform(-20.0, 20.0)));
		for (double d : {0.03, 0.05, 0.2})
			EXPECT_NEAR(ReferenceOverlap::share(ref, cur, pose, d), shareByKdTree(ref, cur, pose, d),
				1.5 / static_cast<double>(cur.size()))
				<< what << " pose " << pose << " distance " << d;
	}
}
}  // namespace

// Exact: the same count as a nearest-neighbour search, on a real pair of
// 361-beam scans (the simulated office, featloc-bench's pair 304) and on
// 360-degree scans, whose bearing windows wrap past +-pi.
TEST(ReferenceOverlap, CountsWhatTheNearestNeighbourSearchCounts)
{
	mrpt::obs::CObservation2DRangeScan a, b;
	mrpt::io::CFileGZInputStream in(
		std::string(FEATLOC_SOURCE_DIR) + "/tests/data/office-1cm-pair-304.rawlog");
	auto ar = mrpt::serialization::archiveFrom(in);
	ar >> a >> b;
	expectSameAsKdTree(ScanPoints::fromScan(a), ScanPoints::fromScan(b), "office pair 304");

	const SyntheticRoom room = SyntheticRoom::office();
	const auto full = [&](const CPose2D& p) {
		return ScanPoints::fromScan(*room.scan(p, CPose2D(), 720, 2 * M_PI * 719 / 720));
	};
	expectSameAsKdTree(full(CPose2D(0.5, 0.2, 0.3)), full(CPose2D(0.7, 0.1, 0.4)), "360 deg");
}

// A point just past -pi is next to one just short of +pi, and the other
// way round.
TEST(ReferenceOverlap, FindsNeighboursAcrossTheSeamAtPi)
{
	const auto points = [](std::initializer_list<double> bearings) {
		ScanPoints s;
		for (double b : bearings)
		{
			ScanPoint p;
			p.bearing = b;
			p.range = 2;
			p.x = 2 * std::cos(b);
			p.y = 2 * std::sin(b);
			s.points.push_back(p);
		}
		return s;
	};
	const double e = 0.001;
	const ScanPoints ref = points({-M_PI / 2, 0.0, M_PI - e});
	EXPECT_EQ(ReferenceOverlap::share(ref, points({-M_PI + e}), CPose2D(), 0.05), 1.0);
	const ScanPoints ref2 = points({-M_PI + e, 0.0, M_PI / 2});
	EXPECT_EQ(ReferenceOverlap::share(ref2, points({M_PI - e}), CPose2D(), 0.05), 1.0);
	EXPECT_EQ(ReferenceOverlap::share(ref2, points({M_PI - 0.1}), CPose2D(), 0.05), 0.0);
}

// The share at the true motion and away from it; stopBelow only cuts the
// count short where the share cannot reach it.
TEST(ReferenceOverlap, StopsCountingOnlyBelowTheShareAsked)
{
	const SyntheticRoom room = SyntheticRoom::office();
	const CPose2D motion(0.3, 0.1, mrpt::DEG2RAD(5));
	const auto ref = ScanPoints::fromScan(*room.scan(CPose2D(0.5, 0.2, 0.3)));
	const auto cur = ScanPoints::fromScan(*room.scan(CPose2D(0.5, 0.2, 0.3) + motion));
	EXPECT_GT(ReferenceOverlap::share(ref, cur, motion, 0.05), 0.9);
	const CPose2D off = motion + CPose2D(0.4, 0, 0);
	const double offShare = ReferenceOverlap::share(ref, cur, off, 0.05);
	EXPECT_LT(offShare, 0.6);
	EXPECT_LT(ReferenceOverlap::share(ref, cur, off, 0.05, 0.85), 0.85);
	EXPECT_DOUBLE_EQ(ReferenceOverlap::share(ref, cur, off, 0.05, offShare), offShare);
	EXPECT_DOUBLE_EQ(ReferenceOverlap::share(ref, cur, motion, 0.05, 0.85),
		ReferenceOverlap::share(ref, cur, motion, 0.05));
	EXPECT_EQ(ReferenceOverlap::share(ref, ScanPoints(), motion, 0.05), 0.0);
}
