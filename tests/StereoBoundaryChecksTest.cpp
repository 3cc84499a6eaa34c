// The checks featloc adds to Moon, Miura & Shirai's boundary search and
// plane association (found on scenes other than the paper's, see
// doc/benchmarks.md), each on a hand-made case.
#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>

#include <cmath>
#include <fstream>

#include "featloc/registerClasses.h"
#include "featloc/stereo/BoundarySearch.h"
#include "featloc/stereo/PlanarRegionExtractor.h"
#include "featloc/stereo/StableVerticalLandmarks.h"
#include "support/TempDir.h"

using namespace featloc;

namespace
{
/** The paper's camera as featloc simulates it (640x480, fx 500 px,
 * baseline 0.12 m), level, camZ above the floor, looking along the robot's x. */
StereoHead paperCamera(double camZ)
{
	StereoHead head;
	head.width = 640;
	head.height = 480;
	head.fx = head.fy = 500;
	head.cx = 319.5;
	head.cy = 239.5;
	head.baseline = 0.12;
	head.camZ = camZ;
	return head;
}
/** A plane filling columns 40..100 of every row, predicted to end at
 * column 100 (end a; its other end b at column 10), and a disparity image
 * with `beyond` past its end (d = 10 on the plane). */
struct HandMadeEnd
{
	PlanarRegion region;
	cv::Mat disparity;
	explicit HandMadeEnd(float beyond)
	{
		region.mask = cv::Mat::zeros(60, 200, CV_8U);
		region.mask.colRange(40, 101).setTo(255);
		region.uA = 100;
		region.sigmaUA = 3;
		region.uB = 10;
		region.sigmaUB = 3;
		region.aInView = region.bInView = true;
		disparity = cv::Mat(60, 200, CV_32F, cv::Scalar(10));
		disparity.colRange(101, 200).setTo(beyond);
	}
};
}  // namespace

TEST(StereoBoundaryChecks, ABoundaryNeedsTheSurfaceBeyondToBeSeenAndNotNearer)
{
	const BoundarySearch search;
	// A farther surface seen past the end: the end is there (the last
	// plane pixel is 100, the boundary half a pixel out).
	const auto farther = search.search(HandMadeEnd(5).region, HandMadeEnd(5).disparity, true, {});
	ASSERT_TRUE(farther.found);
	EXPECT_NEAR(farther.u, 100.5, 0.11);
	EXPECT_EQ(farther.rows, 60u);
	// SAD fattening is in its sigma: half a 15 px block, uniform.
	EXPECT_NEAR(farther.sigma, 15 / (2 * std::sqrt(3.0)), 0.05);

	// Nothing valid past it (a blank wall whose texture fades): no boundary.
	const HandMadeEnd blank(-1);
	const auto faded = search.search(blank.region, blank.disparity, true, {});
	EXPECT_FALSE(faded.found);
	EXPECT_EQ(faded.textureEnds, 60u);

	// Something nearer past it (a person in front): the end is hidden.
	const HandMadeEnd person(25);
	const auto hidden = search.search(person.region, person.disparity, true, {});
	EXPECT_FALSE(hidden.found);
	EXPECT_EQ(hidden.occludedRows, 60u);

	// Too few rows of the wall's height show the end.
	EXPECT_FALSE(search.search(HandMadeEnd(5).region, HandMadeEnd(5).disparity, true, {}, {}, 400).found);
}

TEST(StereoBoundaryChecks, OnlyATallSegmentCanBeTheEdgeAndAloneOnlyWhereThePlaneGoesOn)
{
	const BoundarySearch search;
	const HandMadeEnd blank(-1);  // no disparity boundary
	// A short texture edge near the end is not the edge; a tall one is.
	EXPECT_FALSE(search.search(blank.region, blank.disparity, true, {98}, {10}).found);
	const auto tall = search.search(blank.region, blank.disparity, true, {98}, {50});
	ASSERT_TRUE(tall.found);
	EXPECT_EQ(tall.u, 98);
	EXPECT_EQ(tall.method, "outer segment");
	// ... but only where the map carries the plane on past the end.
	EXPECT_FALSE(search.search(blank.region, blank.disparity, true, {98}, {50}, 0, false).found);

	// The paper's rule: a disparity boundary inward of a tall outer segment
	// moves to it; a short one leaves it.
	const HandMadeEnd seen(5);
	const auto moved = search.search(seen.region, seen.disparity, true, {103}, {55});
	EXPECT_EQ(moved.u, 103);
	const auto kept = search.search(seen.region, seen.disparity, true, {103}, {8});
	EXPECT_NEAR(kept.u, 100.5, 0.11);
}

TEST(StereoBoundaryChecks, CollinearWallsAndWhereAPlaneGoesOn)
{
	registerClasses();
	test::TempDir dir;
	const std::string map = dir.file("map.txt");
	std::ofstream(map) << "# wall, whiteboard on it, a face meeting it at a corner, a wall beyond a door\n"
					   << "0 6 4 6\n1 5.98 2 5.98\n4 6 4 7\n5 6 8 6\n";
	StableVerticalLandmarks x;
	mrpt::config::CConfigFileMemory cfg;
	cfg.write("S", "map", map);
	x.loadParams(cfg, "S");
	ASSERT_EQ(x.walls.size(), 4u);
	EXPECT_TRUE(x.collinear(0, 1));	 // 2 cm apart, parallel
	EXPECT_FALSE(x.collinear(0, 2));  // a corner
	EXPECT_TRUE(x.collinear(0, 3));
	// The whiteboard's ends lie on the wall, which goes on past them.
	EXPECT_TRUE(x.continuesCoplanar(1, true));
	EXPECT_TRUE(x.continuesCoplanar(1, false));
	// The wall's end at x = 4 is a corner and then a door: nothing goes on.
	EXPECT_FALSE(x.continuesCoplanar(0, false));
	EXPECT_FALSE(x.continuesCoplanar(3, true));
}

TEST(StereoBoundaryChecks, NearerWallsHideWhatIsBehindThem)
{
	const StereoHead head = paperCamera(1.0);  // row 240 is 1 m above the floor
	// Robot at the origin looking along +x: a wall 4 m ahead, a desk face
	// 2 m ahead covering the middle of the view.
	const std::vector<MapWall> walls = {{{4, -3}, {4, 3}, "far"}, {{2, -0.4}, {2, 0.4}, "desk"}};
	const PlanarRegionExtractor px;
	const auto depth = px.nearestWallDepth(walls, head, Eigen::Vector3d::Zero());
	ASSERT_EQ(depth.size(), 640u);
	EXPECT_NEAR(depth[320], 2.0, 1e-9);	 // the desk
	EXPECT_NEAR(depth[10], 4.0, 1e-9);	// the wall beside it
	// The far wall's region leaves out the columns the desk hides: with a
	// disparity image that shows the far wall everywhere, its pixels stop
	// at the desk's columns (+- the 3-sigma window).
	cv::Mat disparity(480, 640, CV_32F, cv::Scalar(500 * 0.12 / 4));
	Eigen::Matrix3d S = Eigen::Matrix3d::Identity() * 1e-8;
	const auto seen = px.extract(walls[0], 0, head, Eigen::Vector3d::Zero(), S, disparity, &depth);
	ASSERT_TRUE(seen.fitted) << seen.reason;
	EXPECT_EQ(seen.mask.at<uchar>(240, 320), 0);  // behind the desk
	EXPECT_EQ(seen.mask.at<uchar>(240, 20), 255);
	const auto all = px.extract(walls[0], 0, head, Eigen::Vector3d::Zero(), S, disparity);
	EXPECT_EQ(all.mask.at<uchar>(240, 320), 255);  // without the map's occlusion
}

// A recess's side face seen from outside the recess: the map's nearer wall
// hides it from the predicted pose, but the 3-sigma window around the
// corner still gives it pixels (those of the wall in front). None lies in
// a column where the face itself is visible: it must not become an
// observation of the pose (it put the robot 16 cm off along the stereo
// corridor).
TEST(StereoBoundaryChecks, AFaceHiddenFromThePredictedPoseHasNoVisibleColumns)
{
	const StereoHead head = paperCamera(1.0);
	// The robot at the origin looks along +x; the corridor's wall is at
	// x = 1.2 up to y = 0.5, where a recess goes 0.6 m deeper.
	const std::vector<MapWall> walls = {{{1.2, -3}, {1.2, 0.5}, "wall"}, {{1.2, 0.5}, {1.8, 0.5}, "side"},
		{{1.8, 0.5}, {1.8, 3}, "back"}};
	const PlanarRegionExtractor px;
	const Eigen::Vector3d X = Eigen::Vector3d::Zero();
	const auto depth = px.nearestWallDepth(walls, head, X);
	// The disparity image of what is there, from the true pose (= the prediction).
	cv::Mat disparity(480, 640, CV_32F);
	for (int u = 0; u < 640; u++) disparity.col(u).setTo(head.fx * head.baseline / depth[static_cast<size_t>(u)]);
	// A wide prior (8 cm, 1 deg): the windows reach past the corner.
	const Eigen::Matrix3d S = Eigen::Vector3d(0.08 * 0.08, 0.08 * 0.08, std::pow(M_PI / 180, 2)).asDiagonal();
	const auto side = px.extract(walls[1], 1, head, X, S, disparity, &depth);
	EXPECT_LE(side.visibleColumns, 1u);	 // the corner's own column at most
	EXPECT_GT(side.pixels, 480u);  // the wall in front's, in the window past the corner
	const auto wall = px.extract(walls[0], 0, head, X, S, disparity, &depth);
	ASSERT_TRUE(wall.fitted) << wall.reason;
	EXPECT_GT(wall.visibleColumns, 200u);
	// The wall's observation is fitted to its visible columns alone: the
	// wall is where the map puts it (exact disparities).
	ASSERT_TRUE(wall.visibleFitted);
	EXPECT_NEAR(wall.visibleLine.x(), 0, 0.002);
	EXPECT_NEAR(wall.visibleLine.y(), 0, 0.002);
	EXPECT_GT(wall.viewAngle, 45 * M_PI / 180);	 // seen face on, +-33 deg of the optical axis
	const auto back = px.extract(walls[2], 2, head, X, S, disparity, &depth);
	ASSERT_TRUE(back.fitted) << back.reason;
	EXPECT_GT(back.visibleColumns, 100u);
}

// A table's face (0.75 m high) seen from a camera 1.1 m up: its disparity
// pixels are all below the camera's height, where the table's top is seen
// too. Above the camera it has none, so it is no wall observation, while
// a wall's pixels fill the band above the camera.
TEST(StereoBoundaryChecks, ALowSurfaceHasNoPixelsAboveTheCamera)
{
	const StereoHead head = paperCamera(1.1);
	const std::vector<MapWall> walls = {{{1.5, -0.5}, {1.5, 0.5}, "table"}, {{4, -3}, {4, 3}, "wall"}};
	const PlanarRegionExtractor px;
	const Eigen::Vector3d X = Eigen::Vector3d::Zero();
	const auto depth = px.nearestWallDepth(walls, head, X);
	// The table's face up to 0.75 m, the wall 4 m away above it and beside it.
	cv::Mat disparity(480, 640, CV_32F);
	for (int u = 0; u < 640; u++)
		for (int v = 0; v < 480; v++)
		{
			const double d = depth[static_cast<size_t>(u)];
			const bool table = d < 2 && head.heightAt(v, d) <= 0.75;
			disparity.at<float>(v, u) = static_cast<float>(head.fx * head.baseline / (table ? d : 4.0));
		}
	const Eigen::Matrix3d S = Eigen::Vector3d(1e-4, 1e-4, 1e-6).asDiagonal();
	const auto table = px.extract(walls[0], 0, head, X, S, disparity, &depth);
	EXPECT_GT(table.pixels, 0u) << table.reason;	 // below the camera
	EXPECT_GT(table.visibleColumns, 200u);
	EXPECT_EQ(table.visiblePixels, 0u);
	EXPECT_EQ(table.bandPixels, 0u);
	const auto wall = px.extract(walls[1], 1, head, X, S, disparity, &depth);
	ASSERT_TRUE(wall.fitted) << wall.reason;
	EXPECT_GT(wall.bandPixels, 0.9 * wall.bandRows);
}

// A bookshelf 5 cm in front of a recess's back wall, which goes on 5 cm
// past the shelf's ends and then meets the recess's sides: the plane does
// not "go on" past the shelf's ends (no whiteboard-on-a-wall rule there),
// while a wall that carries on for metres does.
TEST(StereoBoundaryChecks, AStubPastAnEndIsNotThePlaneGoingOn)
{
	registerClasses();
	test::TempDir dir;
	const std::string map = dir.file("map.txt");
	std::ofstream(map) << "6 3 8 3\n6.05 2.95 7.95 2.95\n0 6 4 6\n1 5.98 2 5.98\n";
	StableVerticalLandmarks x;
	mrpt::config::CConfigFileMemory cfg;
	cfg.write("S", "map", map);
	x.loadParams(cfg, "S");
	EXPECT_FALSE(x.continuesCoplanar(1, true));
	EXPECT_FALSE(x.continuesCoplanar(1, false));
	EXPECT_TRUE(x.continuesCoplanar(3, true));	// the whiteboard on its wall
	EXPECT_TRUE(x.continuesCoplanar(3, false));
}

// Whether a plane's end shows a depth step the block matcher can see, from
// the map and the predicted pose: a far wall beyond it (yes), a wall 5 cm
// behind it (no), a nearer wall hiding it (no).
TEST(StereoBoundaryChecks, AnEndIsSearchedOnlyWhereItsDepthStepCanBeSeen)
{
	registerClasses();
	const StereoHead head = paperCamera(1.1);
	const Eigen::Vector3d X = Eigen::Vector3d::Zero();
	const Eigen::Matrix3d S = Eigen::Vector3d(1e-4, 1e-4, 1e-6).asDiagonal();
	const PlanarRegionExtractor px;
	StableVerticalLandmarks x;
	const cv::Mat disparity(480, 640, CV_32F, cv::Scalar(-1));
	// The robot looks along +x; every plane's end b is at y = 0.5 (left in
	// the image), 3 m ahead.
	auto endB = [&](const std::vector<MapWall>& walls) {
		const auto depth = px.nearestWallDepth(walls, head, X);
		const auto r = px.extract(walls[0], 0, head, X, S, disparity, &depth);
		BoundarySearch::Options search;  // the window and evidence process() searches
		search.window_sigmas = x.options.window_sigmas;
		return x.endStepVisible(r, false, head.toCamera(X, walls[0].b).y(), head, depth, search);
	};
	const MapWall plane{{3, -0.5}, {3, 0.5}, "plane"};
	EXPECT_TRUE(endB({plane, {{6, -3}, {6, 3}, "far wall"}}));
	EXPECT_FALSE(endB({plane, {{3.05, -1}, {3.05, 2}, "wall 5 cm behind"}}));
	EXPECT_FALSE(endB({plane, {{6, -3}, {6, 3}, "far wall"}, {{1.5, 0.1}, {1.5, 1.0}, "nearer, hiding the end"}}));
}
