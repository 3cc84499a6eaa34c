#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "featloc/core/InputError.h"
#include "featloc/io/CarmenLogReader.h"
#include "support/ErrorMessage.h"
#include "support/TempDir.h"

using namespace featloc;
using featloc::test::errorMessageOf;
using featloc::test::TempDir;

namespace
{
/** A FLASER line with n ranges. */
std::string flaser(size_t n, double range, double x, double y, double th, double t)
{
	std::ostringstream s;
	s << "FLASER " << n;
	for (size_t i = 0; i < n; i++) s << " " << (i == 1 ? 81.91 : range);
	s << " " << x << " " << y << " " << th << " " << x + 1 << " " << y << " " << th
	  << " 123.4 host " << t << "\n";
	return s.str();
}
}  // namespace

TEST(CarmenLogReader, ReadsFlaserWithTimesPosesOffsetAndSentinels)
{
	TempDir dir;
	std::ofstream(dir.file("a.log"))
		<< "# comment\nPARAM robot_frontlaser_offset -0.04 nohost 0\n"
		<< "ODOM 0 0 0 0 0 0 0 pippo 0\n"
		<< flaser(181, 2.5, 1, 2, 0.5, 10.25) << "NEFF 60\n"
		<< flaser(181, 3.0, 1.5, 2, 0.6, 10.75);
	const auto scans = CarmenLogReader::read(dir.file("a.log"), {});
	ASSERT_EQ(scans.size(), 2u);
	EXPECT_DOUBLE_EQ(scans[0].time, 10.25);
	EXPECT_DOUBLE_EQ(mrpt::Clock::toDouble(scans[1].scan->timestamp), 10.75);
	EXPECT_DOUBLE_EQ(scans[1].pose.x, 1.5);
	EXPECT_DOUBLE_EQ(scans[1].pose.phi, 0.6);
	EXPECT_DOUBLE_EQ(scans[1].odometry.x, 2.5);
	EXPECT_EQ(scans[0].line, 4u);
	const auto& s = *scans[0].scan;
	EXPECT_EQ(s.getScanSize(), 181u);
	EXPECT_FLOAT_EQ(s.aperture, static_cast<float>(M_PI));
	EXPECT_TRUE(s.rightToLeft);
	EXPECT_NEAR(s.sensorPose.x(), -0.04, 1e-12);
	EXPECT_TRUE(s.getScanRangeValidity(0));
	EXPECT_FLOAT_EQ(s.getScanRange(0), 2.5f);
	EXPECT_FALSE(s.getScanRangeValidity(1));  // 81.91: no return
}

TEST(CarmenLogReader, MalformedLinesNameFileAndLine)
{
	TempDir dir;
	std::ofstream(dir.file("short.log")) << "FLASER 181 1 2 3\n";
	std::ofstream(dir.file("bad.log")) << flaser(5, 1.0, 0, 0, 0, 1).replace(9, 1, "x");
	std::ofstream(dir.file("none.log")) << "ODOM 0 0 0 0 0 0 0 h 0\n";
	std::ofstream(dir.file("odom.log")) << "ODOM 0 0 0 0 0 0 0 h 0\nODOM 1 nan 0 0 0 0 0 h 0\n";
	std::ofstream(dir.file("odom2.log")) << "ODOM 1 2\n";
	// The message of reading `name` from the folder, which must fail.
	auto errorOf = [&](const char* name) {
		return errorMessageOf<InputError>([&] { CarmenLogReader::read(dir.file(name), {}); });
	};
	EXPECT_NE(errorOf("short.log").find("short.log:1: FLASER with 181 ranges needs 192 fields"),
		std::string::npos);
	EXPECT_NE(errorOf("bad.log").find("bad.log:1: "), std::string::npos);
	EXPECT_NE(errorOf("none.log").find("no FLASER"), std::string::npos);
	EXPECT_NE(errorOf("odom.log").find("odom.log:2: 'nan' is not a number"), std::string::npos);
	EXPECT_NE(errorOf("odom2.log").find("odom2.log:1: ODOM needs x y theta"), std::string::npos);
	EXPECT_NE(errorOf("nope.log").find("does not exist"), std::string::npos);
}

// Where a FLASER message's beams point: with "sick" (the default) a count
// whose 180 / n deg is a SICK resolution has its beams that far apart from
// -90 deg, ending one step short of +90; 181 and 361 beams span -90..+90;
// "even" spreads any count over -90..+90 (MRPT's carmen2rawlog).
TEST(CarmenLogReader, FlaserBeamsPointWhereTheScannerLooked)
{
	TempDir dir;
	auto bearings = [&](size_t n, const std::string& convention) {
		std::ofstream(dir.file("b.log")) << flaser(n, 2.0, 0, 0, 0, 1);
		CarmenLogReader::Options o;
		o.beamAngles = convention;
		const auto scans = CarmenLogReader::read(dir.file("b.log"), o);
		const auto& s = *scans.at(0).scan;
		EXPECT_EQ(s.getScanSize(), n);
		// A beam's bearing on the robot: the sensor's heading plus MRPT's
		// bearing within the scan.
		std::vector<double> out;
		for (size_t i = 0; i < n; i++) out.push_back(s.sensorPose.yaw() + s.getScanAngle(i));
		return out;
	};
	const double deg = M_PI / 180;
	struct Case
	{
		size_t n;
		std::string convention;
		double first, last;
	};
	for (const Case& c : {Case{180, "sick", -90, 89}, Case{360, "sick", -90, 89.5},
			 Case{720, "sick", -90, 89.75}, Case{181, "sick", -90, 90}, Case{361, "sick", -90, 90},
			 Case{100, "sick", -90, 90}, Case{180, "even", -90, 90}, Case{181, "even", -90, 90}})
	{
		SCOPED_TRACE(testing::Message() << c.n << " beams, " << c.convention);
		const auto b = bearings(c.n, c.convention);
		EXPECT_NEAR(b.front(), c.first * deg, 1e-6);
		EXPECT_NEAR(b.back(), c.last * deg, 1e-6);
		const double step = (c.last - c.first) / static_cast<double>(c.n - 1) * deg;
		for (size_t i = 1; i < b.size(); i++) ASSERT_NEAR(b[i] - b[i - 1], step, 1e-6);
	}
}
