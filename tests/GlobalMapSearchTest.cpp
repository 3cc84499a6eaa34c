#include <gtest/gtest.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CSensoryFrame.h>

#include <cmath>

#include "featloc/eval/TrajectoryFile.h"
#include "featloc/io/RawlogReader.h"
#include "featloc/localization/GlobalMapSearch.h"
#include "featloc/localization/LocalizationMapFile.h"
#include "featloc/math/PoseDifference.h"
#include "featloc/registerClasses.h"
#include "support/CommandRunner.h"
#include "support/TempDir.h"

using namespace featloc;

namespace
{
const std::string kRoot = FEATLOC_SOURCE_DIR;

/** The scans of a featloc-sim rawlog (format #1) with their true poses. */
std::vector<std::pair<mrpt::obs::CObservation2DRangeScan::Ptr, mrpt::poses::CPose2D>> scansWithTruth(
	const std::string& prefix)
{
	registerClasses();
	const Trajectory gt = TrajectoryFile::read(prefix + ".gt.txt");
	std::vector<std::pair<mrpt::obs::CObservation2DRangeScan::Ptr, mrpt::poses::CPose2D>> out;
	RawlogReader reader(prefix + ".rawlog");
	RawlogEntry e;
	while (reader.next(e))
		if (auto sf = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(e.object))
			if (auto scan = sf->getObservationByClass<mrpt::obs::CObservation2DRangeScan>())
			{
				const auto& p = gt.poses[out.size()].pose;
				out.emplace_back(scan, mrpt::poses::CPose2D(p.x, p.y, p.phi));
			}
	return out;
}
}  // namespace

TEST(GlobalMapSearch, FindsTheRobotAnywhereInTheOfficeFromOneScanOrSaysItIsAmbiguous)
{
	LocalizationOptions o;
	o.map = kRoot + "/worlds/office.ini";
	const LocalizationMap map = LocalizationMapFile::load(o);
	const GlobalMapSearch search(map, GlobalMapSearch::Options{});
	const auto scans = scansWithTruth(kRoot + "/rawlogs/sim/office");
	size_t right = 0, wrong = 0, wrongUnambiguous = 0, n = 0;
	double seconds = 0;
	for (size_t k = 0; k < scans.size(); k += 37)
	{
		const auto r = search.search(*scans[k].first);
		ASSERT_TRUE(r.valid);
		n++;
		seconds += r.seconds;
		const Eigen::Vector3d d = poseDifference(r.best, scans[k].second);
		const bool ok = std::hypot(d[0], d[1]) < 0.2 && std::abs(d[2]) < 0.0873;
		right += ok ? 1 : 0;
		if (!ok)
		{
			wrong++;
			wrongUnambiguous += r.rivalScore < 0.9 * r.bestScore ? 1 : 0;
			std::printf("scan %zu: best %s (%.2f), rival %s (%.2f), truth %s\n", k,
				r.best.asString().c_str(), r.bestScore, r.rival.asString().c_str(), r.rivalScore,
				scans[k].second.asString().c_str());
		}
	}
	std::printf("%zu of %zu scans right, %zu wrong (%zu of them without a close rival); %.2f s per search\n",
		right, n, wrong, wrongUnambiguous, seconds / n);
	// Measured: 20 of 20 right. A wrong best must at least have a rival
	// that scores nearly as well (the caller then waits for more scans).
	EXPECT_GE(right, n * 9 / 10);
	EXPECT_EQ(wrongUnambiguous, 0u);
}

// In the twin rooms a robot facing north sees the same walls from either
// room: the search must hand over both places (best, rival or a further
// contender), each distinct from the others and scoring at least
// contenderRatio x the best, so that the hypothesis tracker keeps the true
// one in view while the scans cannot tell them apart.
TEST(GlobalMapSearch, EveryLookAlikePlaceIsHandedOver)
{
	registerClasses();
	LocalizationOptions o;
	o.map = kRoot + "/tests/data/worlds/twin-rooms.ini";
	const LocalizationMap map = LocalizationMapFile::load(o);
	GlobalMapSearch::Options options;
	const GlobalMapSearch search(map, options);
	// A scan from room B, facing north (the world's own first scan).
	featloc::test::TempDir dir;
	const std::string p = dir.file("twin");
	const auto r0 = featloc::test::runCommand(std::string("'") + FEATLOC_SIM_EXE + "' '" + o.map +
		"' --out '" + p + "' -q");
	ASSERT_EQ(r0.exitCode, 0) << r0.output;
	const auto scans = scansWithTruth(p);
	const auto r = search.search(*scans.front().first);
	ASSERT_TRUE(r.valid);
	std::vector<std::pair<mrpt::poses::CPose2D, double>> all = {{r.best, r.bestScore}, {r.rival, r.rivalScore}};
	for (const auto& c : r.contenders) all.emplace_back(c.pose, c.score);
	const mrpt::poses::CPose2D truthB = scans.front().second;
	const mrpt::poses::CPose2D truthA(truthB.x() - 6, truthB.y(), truthB.phi());
	bool seenA = false, seenB = false;
	for (size_t i = 0; i < all.size(); i++)
	{
		EXPECT_GE(all[i].second, options.contenderRatio * r.bestScore - 1e-9);
		for (size_t j = 0; j < i; j++)
			EXPECT_FALSE(posesWithin(all[i].first, all[j].first, options.distinctXY, options.distinctYaw));
		seenA = seenA || posesWithin(all[i].first, truthA, 0.2, 0.0873);
		seenB = seenB || posesWithin(all[i].first, truthB, 0.2, 0.0873);
	}
	EXPECT_TRUE(seenA) << all.size() << " places";
	EXPECT_TRUE(seenB) << all.size() << " places";
	EXPECT_LE(r.contenders.size(), options.maxContenders);
}
