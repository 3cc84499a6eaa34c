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
