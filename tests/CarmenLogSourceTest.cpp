#include <gtest/gtest.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/poses/CPose2D.h>

#include <fstream>
#include <sstream>
#include <vector>

#include "featloc/io/CarmenLogSource.h"
#include "support/TempDir.h"

using namespace featloc;
using featloc::test::TempDir;

namespace
{
/** A FLASER line with 5 ranges: pose (x y th) and odom fields (ox oy oth). */
std::string flaser(const mrpt::poses::CPose2D& pose, const mrpt::poses::CPose2D& odom, double t)
{
	std::ostringstream s;
	s.precision(17);
	s << "FLASER 5 1 1 1 1 1 " << pose.x() << " " << pose.y() << " " << pose.phi() << " "
	  << odom.x() << " " << odom.y() << " " << odom.phi() << " " << t << " host " << t << "\n";
	return s.str();
}

std::string odom(const mrpt::poses::CPose2D& p, double t)
{
	std::ostringstream s;
	s.precision(17);
	s << "ODOM " << p.x() << " " << p.y() << " " << p.phi() << " 0 0 0 " << t << " pippo " << t
	  << "\n";
	return s.str();
}

/** The odometry poses the source gives, in order. */
std::vector<mrpt::poses::CPose2D> odometryOf(CarmenLogSource& source)
{
	std::vector<mrpt::poses::CPose2D> out;
	for (RawlogEntry e; source.next(e);)
		if (auto o = std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(e.object))
			out.push_back(o->odometry);
	return out;
}

/** A corrected log as GMapping/GFS writes it: the wheels move 1 m forward
 * between scans (with a 0.1 rad turn), the corrected poses say something
 * else, and after each FLASER an ODOM message re-anchors the stream at the
 * corrected pose. `skipStep`: the second step has no ODOM message. */
std::string correctedLog(bool skipStep)
{
	const mrpt::poses::CPose2D wheels(1.0, 0.0, 0.1);
	const std::vector<mrpt::poses::CPose2D> corrected = {
		{0, 0, 0}, {0.9, 0.2, 0.15}, {1.7, 0.6, 0.3}};
	std::string log = odom({0, 0, 0}, 0.5);
	for (size_t k = 0; k < corrected.size(); k++)
	{
		const double t = 1.0 + static_cast<double>(k);
		if (k > 0 && !(skipStep && k == 2))
		{
			const mrpt::poses::CPose2D from = corrected[k - 1];
			log += odom(from + mrpt::poses::CPose2D(0.5, 0, 0.05), t - 0.5);
			log += odom(from + wheels, t);
		}
		log += flaser(corrected[k], corrected[k], t) + "NEFF 60\n";
		log += odom(corrected[k], 0);  // the anchor
	}
	return log;
}
}  // namespace

TEST(CarmenLogSource, ACorrectedLogGetsTheWheelOdometryOfItsOdomMessages)
{
	TempDir dir;
	std::ofstream(dir.file("c.log")) << correctedLog(false);
	CarmenLogSource source(dir.file("c.log"));
	EXPECT_NE(source.description().find("odometry: the ODOM messages"), std::string::npos)
		<< source.description();
	const auto odo = odometryOf(source);
	ASSERT_EQ(odo.size(), 3u);
	// Every step's increment is the wheels' (1 m, 0.1 rad), not the
	// corrected poses' (which the FLASER odom fields repeat).
	for (size_t k = 1; k < odo.size(); k++)
	{
		const mrpt::poses::CPose2D d = odo[k] - odo[k - 1];
		EXPECT_NEAR(d.x(), 1.0, 1e-9) << k;
		EXPECT_NEAR(d.y(), 0.0, 1e-9) << k;
		EXPECT_NEAR(d.phi(), 0.1, 1e-9) << k;
	}
}

TEST(CarmenLogSource, ACorrectedLogWhoseOdomMessagesMissAStepGivesNoOdometry)
{
	TempDir dir;
	std::ofstream(dir.file("c.log")) << correctedLog(true);
	CarmenLogSource source(dir.file("c.log"));
	EXPECT_NE(source.description().find("no odometry"), std::string::npos) << source.description();
	EXPECT_NE(source.description().find("miss 1 of 3 scans"), std::string::npos)
		<< source.description();
	size_t scans = 0;
	for (RawlogEntry e; source.next(e);)
	{
		EXPECT_FALSE(std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(e.object));
		scans += std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(e.object) ? 1 : 0;
	}
	EXPECT_EQ(scans, 3u);
	EXPECT_DOUBLE_EQ(source.progress(), 1.0);
}

TEST(CarmenLogSource, ARawLogKeepsItsFlaserOdometryFields)
{
	// A log as recorded: the FLASER odom fields are the wheel odometry at
	// the scan's time, x y theta the localizer's estimate; the ODOM stream
	// is not needed.
	TempDir dir;
	std::ofstream(dir.file("r.log")) << odom({0, 0, 0}, 0.5)
									 << flaser({0, 0, 0}, {5, 5, 0}, 1.0)
									 << odom({5.5, 5, 0}, 1.5)
									 << flaser({0.4, 0, 0}, {6, 5, 0.2}, 2.0);
	CarmenLogSource source(dir.file("r.log"));
	EXPECT_NE(source.description().find("the FLASER messages' odom fields"), std::string::npos)
		<< source.description();
	const auto odo = odometryOf(source);
	ASSERT_EQ(odo.size(), 2u);
	EXPECT_DOUBLE_EQ(odo[0].x(), 5.0);
	EXPECT_DOUBLE_EQ(odo[1].x(), 6.0);
	EXPECT_NEAR(odo[1].phi(), 0.2, 1e-12);
}
