#include <gtest/gtest.h>
#include <mrpt/core/bits_math.h>
#include <mrpt/poses/CPose2D.h>

#include <mrpt/random/RandomGenerators.h>

#include <cmath>

#include "featloc/eval/LoopClosureRelations.h"
#include "featloc/eval/TrajectoryFile.h"
#include "featloc/matchers/ScanMatcherFactory.h"
#include "featloc/registerClasses.h"
#include "support/MatcherTestHelpers.h"
#include "support/SyntheticRoom.h"
#include "support/TempDir.h"

using namespace featloc;
using featloc::test::SyntheticRoom;
using featloc::test::TempDir;
using mrpt::poses::CPose2D;

TEST(LoopClosureRelations, ADriftingTrajectoryIsMeasuredAgainstTheDirectMatchAcrossItsLoop)
{
	registerClasses();
	// Two laps of a 1.5 m circle in the office room, 60 scans a lap: scan k
	// and k + 60 are at the same true place. The estimate drifts: 1 deg of
	// heading and 1 cm per scan, 0.6 m and 60 deg a lap.
	const SyntheticRoom room = SyntheticRoom::office();
	std::vector<mrpt::obs::CObservation2DRangeScan::Ptr> scans;
	std::vector<double> times;
	std::vector<CPose2D> truth;
	Trajectory drifting;
	CPose2D estimate;
	mrpt::random::CRandomGenerator rng(7);
	for (int k = 0; k < 120; k++)
	{
		const double a = 2 * M_PI * k / 60.0;
		truth.emplace_back(-1 + 1.5 * std::cos(a), 0.5 + 1.5 * std::sin(a), a + M_PI / 2);
		// 1 cm of range noise, as a real sensor (doc: CorrelativeScanSearchTest).
		scans.push_back(test::withRangeNoise(room.scan(truth.back()), rng, 0.01));
		times.push_back(100 + 0.1 * k);
		estimate = k == 0 ? truth[0]
						  : estimate + (truth[k] - truth[k - 1]) + CPose2D(0.005, 0, mrpt::DEG2RAD(0.15));
		TimedPose p;
		p.t = times.back();
		p.pose = estimate.asTPose();
		drifting.poses.push_back(p);
	}
	// The wide-basin search makes the reference independent of the
	// drifted guess (9 deg, 0.4 m off). When this test was written: 66
	// revisits, 10 flagged ambiguous, 52 of the 56 relations within 2 cm
	// and 0.5 deg of the truth.
	auto icp = test::configuredMatcher("featloc::IcpMatcher", "coarse_search=true");
	const LoopClosureRelations::Options o;
	const auto r = LoopClosureRelations::find(scans, times, drifting, *icp, o);
	EXPECT_GE(r.relations.size(), 40u) << r.revisits << " revisits, " << r.failed << " failed";
	size_t right = 0;
	for (const auto& rel : r.relations)
	{
		const size_t i = static_cast<size_t>(std::lround((rel.t1 - 100) / 0.1));
		const size_t j = static_cast<size_t>(std::lround((rel.t2 - 100) / 0.1));
		EXPECT_GE(j, i + o.min_gap);
		const CPose2D want = truth[j] - truth[i];
		const CPose2D got(rel.delta);
		right += (got - want).norm() < 0.02 && std::abs(mrpt::math::wrapToPi(got.phi() - want.phi())) < mrpt::DEG2RAD(0.5);
	}
	EXPECT_GE(right, r.relations.size() * 9 / 10) << right << " of " << r.relations.size();
	// Written as featloc-eval reads relations.
	TempDir dir;
	LoopClosureRelations::write(dir.file("loops.txt"), r.relations, "test");
	const auto back = TrajectoryFile::readRelations(dir.file("loops.txt"));
	ASSERT_EQ(back.size(), r.relations.size());
	EXPECT_NEAR(back[0].delta.phi, r.relations[0].delta.phi, 1e-7);
	EXPECT_EQ(TrajectoryFile::detect(dir.file("loops.txt")), TrajectoryFile::Format::Relations);
}

TEST(LoopClosureRelations, ATrajectoryThatNeverComesBackGivesNoRelation)
{
	registerClasses();
	const SyntheticRoom room = SyntheticRoom::office();
	std::vector<mrpt::obs::CObservation2DRangeScan::Ptr> scans;
	std::vector<double> times;
	Trajectory straight;
	for (int k = 0; k < 80; k++)
	{
		const CPose2D p(1 + 0.07 * k, 3, 0);
		scans.push_back(room.scan(p));
		times.push_back(10 + 0.1 * k);
		TimedPose t;
		t.t = times.back();
		t.pose = p.asTPose();
		straight.poses.push_back(t);
	}
	auto icp = ScanMatcherFactory::create("featloc::IcpMatcher");
	const auto r = LoopClosureRelations::find(scans, times, straight, *icp, {});
	EXPECT_EQ(r.revisits, 0u);
	EXPECT_TRUE(r.relations.empty());
}
