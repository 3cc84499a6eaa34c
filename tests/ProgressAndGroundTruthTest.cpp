#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "featloc/eval/TrajectoryEvaluator.h"
#include "featloc/eval/TrajectoryFile.h"
#include "featloc/io/RawlogFileSource.h"
#include "featloc/pipeline/ProgressBar.h"
#include "featloc/registerClasses.h"
#include "support/TempDir.h"
#include "support/TestRawlog.h"

using namespace featloc;
using featloc::test::TempDir;
using featloc::test::TestRawlog;

TEST(Progress, GzipLogProgressFollowsTheEntriesNotTheUncompressedSize)
{
	registerClasses();
	TempDir dir;
	TestRawlog log;
	log.scans = 3000;  // many zlib input buffers of compressed data
	log.compress = true;
	log.write(dir.file("big.rawlog"));
	RawlogFileSource source(dir.file("big.rawlog"));
	std::vector<double> seen;
	for (RawlogEntry e; source.next(e);) seen.push_back(source.progress());
	ASSERT_GT(seen.size(), 100u);
	// Half-way through the entries the fraction is well below 1 (the old
	// uncompressed-position-over-file-size gave 100 % here); not exactly a
	// half, since compressed entries differ in size.
	const double middle = seen[seen.size() / 2];
	EXPECT_GT(middle, 0.2);
	EXPECT_LT(middle, 0.9);
	EXPECT_DOUBLE_EQ(seen.back(), 1.0);
	for (size_t i = 1; i < seen.size(); i++) EXPECT_GE(seen[i], seen[i - 1]);
}

TEST(Progress, HundredPercentOnlyAtTheLastScan)
{
	std::ostringstream out;
	ProgressBar bar(out, false, 0.0);
	bar.update(1.0, 500);  // the reader is at the end of the file, scans remain
	EXPECT_NE(out.str().find(" 99%  500 scans"), std::string::npos) << out.str();
	EXPECT_EQ(out.str().find("100%"), std::string::npos) << out.str();
	bar.done(512);
	EXPECT_NE(out.str().find("100%  512 scans"), std::string::npos) << out.str();
	// Not a terminal: whole lines, one per update.
	const std::string text = out.str();
	EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 2);
	EXPECT_EQ(text.find('\r'), std::string::npos);
}

TEST(GroundTruthFiles, MrptFormatsAreReadAndNamed)
{
	TempDir dir;
	TrajectoryFile::Format f = TrajectoryFile::Format::Auto;
	// kf-slam's robot path: '%' comments, x y z yaw pitch roll, no times.
	const Trajectory path = TrajectoryFile::read(
		std::string(MRPT_DATASETS_DIR) + "/kf-slam_demo_ground_truth_robot_path.txt",
		TrajectoryFile::Format::Auto, &f);
	EXPECT_EQ(f, TrajectoryFile::Format::MrptRobotPath);
	EXPECT_FALSE(path.timed);
	EXPECT_EQ(path.poses.size(), 250u);
	// graphslam-engine's .GT.txt: t x y yaw.
	const Trajectory gt = TrajectoryFile::read(std::string(MRPT_DATASETS_DIR) +
			"/graphslam-engine-demos/action_observations_map/simul.rawlog.GT.txt",
		TrajectoryFile::Format::Auto, &f);
	EXPECT_EQ(f, TrajectoryFile::Format::TimeXYYaw);
	EXPECT_TRUE(gt.timed);
	EXPECT_GT(gt.poses.size(), 1000u);
	// '%' comments on a t x y yaw file.
	std::ofstream(dir.file("pct.txt")) << "% t x y yaw\n%\n1.0 0 0 0\n2.0 1 0 0.5\n";
	EXPECT_EQ(TrajectoryFile::read(dir.file("pct.txt")).poses.size(), 2u);
	EXPECT_NE(TrajectoryFile::formatDescription(f).find("t x y yaw"), std::string::npos);
}

TEST(GroundTruthFiles, KittiRowsInBothConventionsAndIndexAssociation)
{
	TempDir dir;
	const double th = 0.3, c = std::cos(th), s = std::sin(th);
	{
		// Z up: rotation about z, translation (2, 3).
		std::ofstream f(dir.file("zup.txt"));
		f << "1 0 0 0 0 1 0 0 0 0 1 0\n";
		f << c << " " << -s << " 0 2 " << s << " " << c << " 0 3 0 0 1 0\n";
		// KITTI's camera frame: rotation about y, forward = z; a left turn of
		// th is a rotation of -th about y; position 3 m ahead, 2 m right.
		std::ofstream k(dir.file("cam.txt"));
		k << "1 0 0 0 0 1 0 0 0 0 1 0\n";
		k << c << " 0 " << -s << " 2 0 1 0 0 " << s << " 0 " << c << " 3\n";
	}
	TrajectoryFile::Format f;
	const Trajectory z = TrajectoryFile::read(dir.file("zup.txt"), TrajectoryFile::Format::Auto, &f);
	EXPECT_EQ(f, TrajectoryFile::Format::Kitti);
	EXPECT_NEAR(z.poses[1].pose.x, 2, 1e-9);
	EXPECT_NEAR(z.poses[1].pose.y, 3, 1e-9);
	EXPECT_NEAR(z.poses[1].pose.phi, th, 1e-6);
	const Trajectory k = TrajectoryFile::read(dir.file("cam.txt"));
	EXPECT_NEAR(k.poses[1].pose.x, 3, 1e-9);
	EXPECT_NEAR(k.poses[1].pose.y, -2, 1e-9);
	EXPECT_NEAR(k.poses[1].pose.phi, th, 1e-6);

	// Untimed rows pair with the estimate's rows in order.
	Trajectory est;
	for (size_t i = 0; i < 2; i++)
	{
		TimedPose p;
		p.t = 100.0 + static_cast<double>(i);
		p.pose = z.poses[i].pose;
		est.poses.push_back(p);
	}
	const EvaluationReport rep = TrajectoryEvaluator(0.01).evaluate(z, est);
	EXPECT_EQ(rep.associated, 2u);
	EXPECT_NEAR(rep.ate.rmse, 0, 1e-6);
}
