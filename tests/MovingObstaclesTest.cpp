// Doors that swing and carts that are pushed (featloc-sim): what the laser
// sees of them, the world file's keys and their errors, and which beams
// featloc-bench counts as on something that moved.
#include <gtest/gtest.h>
#include <mrpt/core/bits_math.h>
#include <mrpt/poses/CPose3D.h>

#include <cmath>

#include "featloc/config/TrackedConfig.h"
#include "featloc/core/ConfigError.h"
#include "featloc/sim/MovedSurfaceBeams.h"
#include "featloc/sim/RangeScanFisherInformation.h"
#include "featloc/sim/SimWorld.h"
#include "support/ErrorMessage.h"

using namespace featloc;
using mrpt::poses::CPose2D;

namespace
{
/** A 6 x 4 m room, a door on its west wall (closed along it at 90 deg,
 * open into the room at 0 deg), a cart crossing it with stops. */
const char* kRoom = R"(
[Wall.room]
polyline = [0 1.9; 0 4; 6 4; 6 0; 0 0; 0 1]
[Door.west]
hinge  = [0 1]
length = 0.9
swing  = [0 90; 2 90; 4 0; 8 0]
period = 10
[Agent.cart]
shape     = cart
cart_size = [1.0 0.6]
waypoints = [2 3; 5 3]
speed     = 0.5
pause     = 2
mode      = pingpong
)";

SimWorld room()
{
	TrackedConfig c;
	c.loadText(kRoom, "room.ini");
	return SimWorld::fromConfig(c);
}

/** A 361-beam, 360-degree scan of the world's exact ranges at time t. */
mrpt::obs::CObservation2DRangeScan exactScan(const SimWorld& w, const CPose2D& robot, double t)
{
	mrpt::obs::CObservation2DRangeScan s;
	s.aperture = static_cast<float>(2 * M_PI * 360 / 361);
	s.rightToLeft = true;
	s.maxRange = 30;
	s.stdError = 0.01f;
	s.resizeScan(361);
	std::vector<double> r;
	w.castScan(t, robot, s, r);
	for (size_t i = 0; i < 361; i++)
	{
		s.setScanRange(i, static_cast<float>(std::isfinite(r[i]) ? r[i] : 30));
		s.setScanRangeValidity(i, std::isfinite(r[i]));
	}
	return s;
}
}  // namespace

// The door's angle is piecewise linear between keyframes and repeats with
// its period (from the last keyframe back round to the first); the cart is
// a rectangle along its heading; both are segments after the static ones.
TEST(MovingObstacles, DoorsSwingAndCartsAreRectangles)
{
	const SimWorld w = room();
	ASSERT_EQ(w.doors().size(), 1u);
	const SwingingDoor& d = w.doors().front();
	EXPECT_NEAR(mrpt::RAD2DEG(d.angleAt(1)), 90, 1e-9);
	EXPECT_NEAR(mrpt::RAD2DEG(d.angleAt(3)), 45, 1e-9);
	EXPECT_NEAR(mrpt::RAD2DEG(d.angleAt(6)), 0, 1e-9);
	EXPECT_NEAR(mrpt::RAD2DEG(d.angleAt(9)), 45, 1e-9);	 // 8 -> 10 (= 0): 0 -> 90
	EXPECT_NEAR(mrpt::RAD2DEG(d.angleAt(13)), 45, 1e-9);	 // the next period
	const WallSegment open = d.segmentAt(6);
	EXPECT_NEAR(open.b.x, 0.9, 1e-12);
	EXPECT_NEAR(open.b.y, 1.0, 1e-12);

	std::vector<WallSegment> scratch;
	const auto& segs = w.segmentsAt(0, scratch);
	ASSERT_EQ(segs.size(), w.segments().size() + 1 + 4);
	// The cart at its first waypoint, heading +x: corners at 2 +- 0.5, 3 +- 0.3.
	double xmin = 1e9, xmax = -1e9, ymin = 1e9, ymax = -1e9;
	for (size_t k = w.segments().size() + 1; k < segs.size(); k++)
		for (const auto& p : {segs[k].a, segs[k].b})
		{
			xmin = std::min(xmin, p.x), xmax = std::max(xmax, p.x);
			ymin = std::min(ymin, p.y), ymax = std::max(ymax, p.y);
		}
	EXPECT_NEAR(xmin, 1.5, 1e-9);
	EXPECT_NEAR(xmax, 2.5, 1e-9);
	EXPECT_NEAR(ymin, 2.7, 1e-9);
	EXPECT_NEAR(ymax, 3.3, 1e-9);
	// A world without doors and carts gives its own segments, uncopied.
	TrackedConfig plain;
	plain.loadText("[Wall.w]\npolyline = [0 0; 1 0]\n", "plain.ini");
	const SimWorld still = SimWorld::fromConfig(plain);
	EXPECT_EQ(&still.segmentsAt(5, scratch), &still.segments());
}

// Beams on the door or the cart carry no information about the pose; and
// featloc-bench counts them as moved only when the thing moved between the
// two scans (the cart standing at a waypoint, the door held open: not).
TEST(MovingObstacles, BeamsOnThingsThatMovedAreToldApart)
{
	const SimWorld w = room();
	const CPose2D robot(3, 1.5, 0);
	const auto swinging = exactScan(w, robot, 3.0);	 // the door at 45 deg, the cart moving
	const auto fisher = RangeScanFisherInformation::of(w, 3.0, swinging, robot);
	size_t valid = 0;
	for (size_t i = 0; i < swinging.getScanSize(); i++) valid += swinging.getScanRangeValidity(i);
	EXPECT_EQ(fisher.beamsOff, 0u);
	EXPECT_LT(fisher.beamsUsed, valid);	 // beams on the door and the cart left out

	const auto moved = MovedSurfaceBeams::of(w, 3.0, swinging, robot, 2.8);
	EXPECT_GT(moved.size(), 5u);
	EXPECT_TRUE(std::is_sorted(moved.begin(), moved.end()));
	EXPECT_TRUE(MovedSurfaceBeams::of(w, 3.0, swinging, robot, 3.0).empty());
	// t = 6..8: the cart stands at (5, 3) (its pause), the door is held open.
	const auto standing = exactScan(w, robot, 7.5);
	EXPECT_TRUE(MovedSurfaceBeams::of(w, 7.5, standing, robot, 6.5).empty());
}

TEST(MovingObstacles, BadDoorsAndCartsNameTheirKey)
{
	const std::pair<const char*, const char*> cases[] = {
		{"[Door.d]\nhinge = [0 0]\nswing = [0 90; 0 45]\n", "swing"},
		{"[Door.d]\nhinge = [0 0]\nswing = [0 90; 12 45]\nperiod = 10\n", "swing"},
		{"[Door.d]\nhinge = [0 0 1]\nswing = [0 90]\n", "hinge"},
		{"[Door.d]\nhinge = [0 0]\nswing = [0 90]\nlength = 0\n", "length"},
		{"[Agent.c]\nshape = cart\ncart_size = [1 -0.6]\nwaypoints = [0 0; 1 0]\n", "cart_size"},
	};
	for (const auto& [text, key] : cases)
	{
		TrackedConfig c;
		c.loadText(std::string("[Wall.w]\npolyline = [0 0; 1 0]\n") + text, "bad.ini");
		const std::string what =
			featloc::test::errorMessageOf<ConfigError>([&] { SimWorld::fromConfig(c); });
		EXPECT_NE(what.find(key), std::string::npos) << text << " -> " << what;
		EXPECT_NE(what.find("bad.ini"), std::string::npos) << what;
	}
}
