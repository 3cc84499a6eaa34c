// Steps clocked by any observation: which observations make one step, at
// which time, with which odometry; classes nobody handles; logs without a
// laser (odometry + landmarks), end to end with MRPT's own EKF-SLAM demo.
#include <gtest/gtest.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationBearingRange.h>
#include <mrpt/obs/CObservationComment.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CObservationRobotPose.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>

#include <cmath>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "featloc/eval/TrajectoryFile.h"
#include "featloc/io/RawlogReader.h"
#include "featloc/pipeline/StepAssembler.h"
#include "featloc/registerClasses.h"
#include "support/CommandRunner.h"
#include "support/TempDir.h"

using namespace featloc;
using featloc::test::CommandResult;
using featloc::test::runCommand;
using featloc::test::shellQuote;
using featloc::test::TempDir;
using mrpt::poses::CPose2D;

namespace
{
const std::string kRun = FEATLOC_RUN_EXE;
const std::string kConfig = std::string(FEATLOC_SOURCE_DIR) + "/config.ini";
const std::string kDatasets = "/usr/share/mrpt/datasets/";
constexpr double kT0 = 5000.0;

mrpt::Clock::time_point at(double t) { return mrpt::Clock::fromDouble(kT0 + t); }

mrpt::obs::CObservation2DRangeScan::Ptr scanAt(double t)
{
	auto s = std::make_shared<mrpt::obs::CObservation2DRangeScan>();
	s->sensorLabel = "LASER";
	s->timestamp = at(t);
	s->aperture = static_cast<float>(M_PI);
	s->maxRange = 20;
	s->resizeScan(181);
	for (size_t i = 0; i < 181; i++) s->setScanRange(i, 2.0f), s->setScanRangeValidity(i, true);
	return s;
}

mrpt::obs::CObservationBearingRange::Ptr landmarksAt(double t, std::vector<float> ranges)
{
	auto o = std::make_shared<mrpt::obs::CObservationBearingRange>();
	o->sensorLabel = "BEACONS";
	o->timestamp = at(t);
	o->sensor_std_range = 0.03f;
	o->sensor_std_yaw = 0.01f;
	for (size_t i = 0; i < ranges.size(); i++)
	{
		mrpt::obs::CObservationBearingRange::TMeasurement m;
		m.range = ranges[i];
		m.yaw = 0.3f * static_cast<float>(i);
		m.pitch = 0;
		m.landmarkID = static_cast<int32_t>(i);
		o->sensedData.push_back(m);
	}
	return o;
}

mrpt::obs::CObservationOdometry::Ptr odometryAt(double t)
{
	auto o = std::make_shared<mrpt::obs::CObservationOdometry>();
	o->sensorLabel = "ODOMETRY";
	o->timestamp = at(t);
	o->odometry = CPose2D(t, 0, 0);	 // 1 m/s straight ahead
	return o;
}

mrpt::obs::CActionCollection actionOf(const CPose2D& motion)
{
	mrpt::obs::CActionRobotMovement2D move;
	mrpt::obs::CActionRobotMovement2D::TMotionModelOptions opts;
	move.computeFromOdometry(motion, opts);
	mrpt::obs::CActionCollection acts;
	acts.insert(move);
	return acts;
}

/** Writes the objects in order as a rawlog. */
void writeLog(const std::string& file, const std::vector<mrpt::serialization::CSerializable::Ptr>& objects)
{
	mrpt::io::CFileGZOutputStream f(file);
	auto arch = mrpt::serialization::archiveFrom(f);
	for (const auto& o : objects) arch << *o;
}

mrpt::obs::CSensoryFrame::Ptr frameOf(const std::vector<mrpt::obs::CObservation::Ptr>& obs)
{
	auto sf = std::make_shared<mrpt::obs::CSensoryFrame>();
	for (const auto& o : obs) sf->insert(o);
	return sf;
}

/** The steps of a log; `allUsed` (if given) gets every observation used. */
std::vector<EstimationStep> stepsOf(
	const std::string& file, StepAssembler& a, std::vector<StepSource>* allUsed = nullptr)
{
	RawlogReader reader(file);
	std::vector<EstimationStep> steps;
	std::vector<StepSource> used;
	RawlogEntry e;
	while (reader.next(e))
	{
		used.clear();
		a.push(e, used, steps);
		if (allUsed) allUsed->insert(allUsed->end(), used.begin(), used.end());
	}
	a.finish(steps);
	return steps;
}
}  // namespace

// Odometry readings, and sensory frames holding a scan and, 50 ms later, a
// range-bearing observation: the landmarks are applied at their own time,
// with the motion since the scan, not one scan late.
TEST(ObservationFrames, RangeBearingAfterTheScanInOneFrameIsAppliedAtItsOwnTime)
{
	registerClasses();
	TempDir dir;
	std::vector<mrpt::serialization::CSerializable::Ptr> log;
	for (int k = 0; k <= 10; k++)
	{
		const double t = 0.1 * k;
		log.push_back(odometryAt(t));
		if (k == 2 || k == 5) log.push_back(frameOf({scanAt(t), landmarksAt(t + 0.05, {3, 4})}));
	}
	writeLog(dir.file("a.rawlog"), log);
	StepAssembler a(InputOptions{}, OdometryOptions{}, "a");
	const auto steps = stepsOf(dir.file("a.rawlog"), a);
	ASSERT_EQ(steps.size(), 4u);
	const double times[] = {0.2, 0.25, 0.5, 0.55};
	for (size_t k = 0; k < 4; k++)
	{
		EXPECT_NEAR(mrpt::Clock::toDouble(steps[k].time) - kT0, times[k], 1e-6) << k;
		EXPECT_EQ(steps[k].scan != nullptr, k % 2 == 0) << k;
		EXPECT_EQ(steps[k].landmarks.size(), k % 2 == 0 ? 0u : 2u) << k;
	}
	// The motion to each step is the odometry between the two times.
	EXPECT_NEAR(steps[1].odometry.mean.x(), 0.05, 1e-9);
	EXPECT_NEAR(steps[2].odometry.mean.x(), 0.25, 1e-9);
	EXPECT_NEAR(steps[3].odometry.mean.x(), 0.05, 1e-9);
	EXPECT_EQ(steps[2].scanIndex, 1u);
}

// Format #1: the action is the motion to the next frame, and a frame is
// one robot pose: its scan and landmarks make one step together.
TEST(ObservationFrames, WithActionsTheSensoryFrameIsOneStep)
{
	registerClasses();
	TempDir dir;
	std::vector<mrpt::serialization::CSerializable::Ptr> log;
	for (int k = 0; k < 4; k++)
	{
		const double t = 0.1 * k;
		if (k > 0) log.push_back(std::make_shared<mrpt::obs::CActionCollection>(actionOf(CPose2D(0.1, 0, 0))));
		log.push_back(frameOf({scanAt(t), landmarksAt(t + 0.01, {3})}));
	}
	writeLog(dir.file("b.rawlog"), log);
	StepAssembler a(InputOptions{}, OdometryOptions{}, "b");
	const auto steps = stepsOf(dir.file("b.rawlog"), a);
	ASSERT_EQ(steps.size(), 4u);
	for (size_t k = 0; k < 4; k++)
	{
		EXPECT_TRUE(steps[k].scan != nullptr) << k;
		EXPECT_EQ(steps[k].landmarks.size(), 1u) << k;	// its own frame's, not the next
		EXPECT_NEAR(mrpt::Clock::toDouble(steps[k].time) - kT0, 0.1 * static_cast<double>(k), 1e-6);
		if (k > 0) { EXPECT_NEAR(steps[k].odometry.mean.x(), 0.1, 1e-9); }
	}
}

// No laser at all: every frame of odometry + landmarks is a step, and a
// class nobody handles is counted, not an error.
TEST(ObservationFrames, OdometryAndLandmarksOnlyAndAnUnhandledClass)
{
	registerClasses();
	TempDir dir;
	std::vector<mrpt::serialization::CSerializable::Ptr> log;
	for (int k = 0; k < 5; k++)
	{
		if (k > 0) log.push_back(std::make_shared<mrpt::obs::CActionCollection>(actionOf(CPose2D(0.2, 0, 0.1))));
		auto note = std::make_shared<mrpt::obs::CObservationComment>();
		note->timestamp = at(0.1 * k);
		note->text = "operator note";
		log.push_back(frameOf({landmarksAt(0.1 * k, {2, 3, 4}), note}));
	}
	writeLog(dir.file("c.rawlog"), log);
	StepAssembler a(InputOptions{}, OdometryOptions{}, "c");
	const auto steps = stepsOf(dir.file("c.rawlog"), a);
	ASSERT_EQ(steps.size(), 5u);
	for (const auto& s : steps)
	{
		EXPECT_EQ(s.scan, nullptr);
		EXPECT_EQ(s.landmarks.size(), 3u);
	}
	ASSERT_EQ(a.ignoredObservations().size(), 1u);
	EXPECT_EQ(a.ignoredObservations().begin()->second, 5u);
	EXPECT_NE(a.ignoredObservations().begin()->first.find("CObservationComment"), std::string::npos);
}

// featloc-run on the unhandled-class log: it runs (summary.json counts
// what was ignored); on a log with nothing usable: an error naming what
// the log holds.
TEST(ObservationFrames, AppCountsIgnoredClassesAndNamesWhatAnUnusableLogHolds)
{
	registerClasses();
	TempDir dir;
	std::vector<mrpt::serialization::CSerializable::Ptr> usable, unusable;
	for (int k = 0; k < 3; k++)
	{
		auto note = std::make_shared<mrpt::obs::CObservationComment>();
		note->timestamp = at(0.1 * k);
		note->text = "note";
		usable.push_back(frameOf({landmarksAt(0.1 * k, {2, 3}), note}));
		unusable.push_back(note);
		unusable.push_back(odometryAt(0.1 * k));
	}
	writeLog(dir.file("usable.rawlog"), usable);
	writeLog(dir.file("unusable.rawlog"), unusable);
	CommandResult r = runCommand(
		shellQuote(kRun) + " " + shellQuote(kConfig) + " " + shellQuote(dir.file("usable.rawlog")) +
		" -q --set Pipeline:estimator=ekf --out " + shellQuote(dir.file("o1")));
	ASSERT_EQ(r.exitCode, 0) << r.output;
	std::ifstream in(dir.file("o1/summary.json"));
	const auto j = nlohmann::json::parse(in);
	EXPECT_EQ(j["counts"]["steps"], 3);
	EXPECT_EQ(j["counts"]["ignored_observations"].size(), 1u) << j["counts"].dump();

	r = runCommand(
		shellQuote(kRun) + " " + shellQuote(kConfig) + " " +
		shellQuote(dir.file("unusable.rawlog")) + " -q --out " + shellQuote(dir.file("o2")));
	EXPECT_EQ(r.exitCode, 1) << r.output;
	EXPECT_NE(r.output.find("has nothing featloc can use"), std::string::npos) << r.output;
	EXPECT_NE(r.output.find("3 mrpt::obs::CObservationComment"), std::string::npos) << r.output;
	EXPECT_NE(r.output.find("3 mrpt::obs::CObservationOdometry"), std::string::npos) << r.output;
}

// MRPT's EKF-SLAM demo (odometry + range-bearing landmarks, no laser) runs
// with estimator = ekf: one pose per step, and the path and map are as good
// as MRPT's own kf-slam's on the same log (its figures, measured by
// scripts/bench-landmarks.sh: ATE 5.2 mm, landmark error mean 3.68 mm,
// max 12.5 mm).
TEST(ObservationFrames, MrptKfSlamDemoRunsAndMatchesMrptsKfSlam)
{
	const std::string log = kDatasets + "kf-slam_demo.rawlog";
	const std::string gtPath = kDatasets + "kf-slam_demo_ground_truth_robot_path.txt";
	const std::string gtLandmarks = kDatasets + "kf-slam_demo_ground_truth.txt";
	TempDir dir;
	const CommandResult r = runCommand(
		shellQuote(kRun) + " " + shellQuote(kConfig) + " " + shellQuote(log) +
		" -q --set Pipeline:estimator=ekf --set Evaluation:ground_truth=" + shellQuote(gtPath) +
		" --out " + shellQuote(dir.file("o")));
	ASSERT_EQ(r.exitCode, 0) << r.output;
	const Trajectory est = TrajectoryFile::read(dir.file("o/poses_cov.txt"));
	const Trajectory gt = TrajectoryFile::read(gtPath);
	EXPECT_EQ(est.poses.size(), gt.poses.size());  // one pose per step
	std::ifstream in(dir.file("o/summary.json"));
	const auto j = nlohmann::json::parse(in);
	EXPECT_LT(j["evaluation"]["ate_m"]["rmse"].get<double>(), 0.0052) << j.dump(2);
	// estimated.rawlog: every step's pose, in the frame it was estimated for.
	{
		RawlogReader reader(dir.file("o/estimated.rawlog"));
		RawlogEntry e;
		size_t poses = 0, frames = 0;
		while (reader.next(e))
			if (auto sf = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(e.object))
			{
				frames++;
				for (const auto& o : *sf)
					if (IS_CLASS(*o, mrpt::obs::CObservationRobotPose)) poses++;
			}
		EXPECT_EQ(poses, est.poses.size());
		EXPECT_EQ(frames, est.poses.size());
	}

	std::map<int64_t, std::pair<double, double>> truth;
	{
		std::ifstream g(gtLandmarks);
		double v[7];
		while (g >> v[0] >> v[1] >> v[2] >> v[3] >> v[4] >> v[5] >> v[6])
			truth[static_cast<int64_t>(v[6])] = {v[0], v[1]};
	}
	std::ifstream lm(dir.file("o/landmarks.txt"));
	std::string line;
	double sum = 0, worst = 0;
	size_t n = 0;
	while (std::getline(lm, line))
	{
		if (line.empty() || line[0] == '#') continue;
		std::istringstream ss(line);
		int64_t id;
		double x, y;
		ss >> id >> x >> y;
		ASSERT_TRUE(truth.count(id)) << line;
		const double e = std::hypot(x - truth[id].first, y - truth[id].second);
		sum += e;
		worst = std::max(worst, e);
		n++;
	}
	EXPECT_EQ(n, truth.size());
	EXPECT_LT(sum / static_cast<double>(n), 0.00368);
	EXPECT_LT(worst, 0.0125);
}

// Format #2 as featloc-sim writes it: the landmarks, then the scan, at one
// time: one step, whose pose the outputs attach to the scan.
TEST(ObservationFrames, ObservationsSharingATimeMakeOneStepAttachedToTheScan)
{
	registerClasses();
	TempDir dir;
	std::vector<mrpt::serialization::CSerializable::Ptr> log;
	for (int k = 0; k <= 6; k++)
	{
		const double t = 0.1 * k;
		log.push_back(odometryAt(t));
		if (k % 2 == 0)
		{
			log.push_back(landmarksAt(t, {2, 3}));
			log.push_back(scanAt(t));
		}
	}
	writeLog(dir.file("d.rawlog"), log);
	StepAssembler a(InputOptions{}, OdometryOptions{}, "d");
	std::vector<StepSource> allUsed;
	const auto steps = stepsOf(dir.file("d.rawlog"), a, &allUsed);
	ASSERT_EQ(steps.size(), 4u);
	for (const auto& s : steps)
	{
		ASSERT_NE(s.scan, nullptr);
		EXPECT_EQ(s.landmarks.size(), 2u);
		EXPECT_EQ(s.source, static_cast<const mrpt::obs::CObservation*>(s.scan.get()))
			<< "step " << s.index;
	}
	EXPECT_EQ(allUsed.size(), 8u);	// both observations of each step were used
	EXPECT_NEAR(steps[1].odometry.mean.x(), 0.2, 1e-9);
}
