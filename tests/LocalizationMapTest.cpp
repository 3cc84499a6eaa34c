#include <gtest/gtest.h>
#include <mrpt/config/CConfigFile.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "featloc/localization/LocalizationMapFile.h"
#include "featloc/sim/RayCaster.h"
#include "featloc/sim/SimWorld.h"
#include "support/SyntheticRoom.h"

using namespace featloc;

namespace
{
const std::string kOffice = std::string(FEATLOC_SOURCE_DIR) + "/worlds/office.ini";

mrpt::obs::CObservation2DRangeScan sickLike()
{
	mrpt::obs::CObservation2DRangeScan s;
	s.aperture = M_PI;
	s.rightToLeft = true;
	s.maxRange = 30;
	s.sensorPose = mrpt::poses::CPose3D(0.2, 0, 0, 0, 0, 0);
	s.resizeScan(361);
	return s;
}
}  // namespace

// The virtual scan is what the matcher takes as the map's reference: cast
// from a pose, it must give the ranges the real sensor measures there, with
// no bias (a bias is a pose error of the whole run in the map frame).
TEST(LocalizationMap, VirtualScanOfAWorldFileGivesTheExactRangesWithoutBias)
{
	LocalizationOptions o;
	o.map = kOffice;
	const LocalizationMap map = LocalizationMapFile::load(o);
	EXPECT_EQ(map.kind(), "world");
	EXPECT_NEAR(map.grid().getResolution(), 0.02, 1e-6);

	mrpt::config::CConfigFile cfg(kOffice);
	const SimWorld world = SimWorld::fromConfig(cfg);
	const auto like = sickLike();
	std::vector<double> diff;
	for (const mrpt::poses::CPose2D& pose :
		 {mrpt::poses::CPose2D(2.0, 8.0, 0.0), mrpt::poses::CPose2D(12.3, 7.9, 0.4),
			 mrpt::poses::CPose2D(17.6, 11.2, 1.6), mrpt::poses::CPose2D(27.5, 4.1, -2.0),
			 mrpt::poses::CPose2D(33.1, 8.05, 3.1)})
	{
		const auto v = map.virtualScan(like, pose);
		ASSERT_EQ(v.getScanSize(), like.getScanSize());
		const auto sensor = pose + mrpt::poses::CPose2D(0.2, 0, 0);
		std::vector<double> exact;
		RayCaster::cast(sensor.asTPose(), -M_PI / 2, M_PI / 360, 361, 30, world.segments(),
			world.circles(), exact);
		for (size_t i = 0; i < exact.size(); i++)
			if (std::isfinite(exact[i]) && v.getScanRangeValidity(i))
				diff.push_back(v.getScanRange(i) - exact[i]);
	}
	ASSERT_GT(diff.size(), 1500u);
	// Beams that graze a corner or a door frame may hit another surface
	// in the grid: counted, and left out of the bias.
	std::vector<double> onSurface, absd;
	for (double d : diff)
		if (std::abs(d) < 0.05) onSurface.push_back(d), absd.push_back(std::abs(d));
	const double mean =
		std::accumulate(onSurface.begin(), onSurface.end(), 0.0) / onSurface.size();
	std::nth_element(absd.begin(), absd.begin() + absd.size() / 2, absd.end());
	const double median = absd[absd.size() / 2];
	std::printf("virtual - exact range: %zu of %zu beams within 5 cm, their mean %.4f m, median "
				"|d| %.4f m\n",
		onSurface.size(), diff.size(), mean, median);
	EXPECT_GT(onSurface.size(), 0.95 * diff.size());
	EXPECT_LT(std::abs(mean), 0.003);
	EXPECT_LT(median, 0.008);
}

// A beam that ends beyond where the map stops it passes through something
// the map has there (negative information, the beam model's half the end
// points' score leaves out): at the pose the scan was taken from, no beam
// does; one room over, where the map has a desk the scan does not show, the
// beams through the desk do.
TEST(LocalizationMap, BeamsThatPassThroughTheMapAreCounted)
{
	LocalizationOptions o;
	o.map = std::string(FEATLOC_SOURCE_DIR) + "/tests/data/worlds/twin-rooms-desk.ini";
	const LocalizationMap map = LocalizationMapFile::load(o);
	// The scan of room B (no desk), facing north from its middle.
	const mrpt::poses::CPose2D inB(8, 2, M_PI / 2);
	const auto scan = *featloc::test::SyntheticRoom::fromWorldFile(o.map, 0).scan(
		inB, mrpt::poses::CPose2D(0.2, 0, 0));
	EXPECT_EQ(map.shareSeenThrough(scan, inB), 0.0);
	// Room A is room B moved 6 m west, with a desk 1.2 m in front of the
	// robot (1 m wide): the beams that end on A's north wall pass through
	// it. The end points themselves all lie on A's walls.
	const mrpt::poses::CPose2D inA(2, 2, M_PI / 2);
	const double share = map.shareSeenThrough(scan, inA);
	EXPECT_GT(share, 0.1) << share;
	EXPECT_LT(share, 0.4) << share;
	// A scan that ends nowhere (no valid beam) sees through nothing.
	auto blind = sickLike();
	for (size_t i = 0; i < blind.getScanSize(); i++) blind.setScanRangeValidity(i, false);
	EXPECT_EQ(map.shareSeenThrough(blind, inA), 0.0);
}
