// Stereo live (issue 13, item 6): MRPT's CCameraSensor with grabber_type =
// rawlog replaying the emulator's camera recording, beside MRPT's
// CHokuyoURG and featloc's TcpOdometrySensor on loopback, into the stereo
// landmarks and the EKF; and the replay clock that makes a recording a
// camera.
#include <gtest/gtest.h>
#include <mrpt/core/Clock.h>
#include <mrpt/obs/CObservationStereoImages.h>

#include <map>

#include "featloc/io/RawlogReader.h"
#include "featloc/live/RecordingReplayClock.h"
#include "support/CommandRunner.h"
#include "support/DataRows.h"
#include "support/FreePort.h"
#include "support/JsonFile.h"
#include "support/LiveEmulator.h"
#include "support/TempDir.h"

using namespace featloc;
using namespace featloc::test;

namespace
{
/** The stereo pairs of a rawlog: stamp -> whether both images are held in
 * memory (not files). */
std::map<double, bool> stereoPairs(const std::string& rawlog)
{
	RawlogReader reader(rawlog);
	RawlogEntry e;
	std::map<double, bool> pairs;
	while (reader.next(e))
		if (auto p = std::dynamic_pointer_cast<mrpt::obs::CObservationStereoImages>(e.object))
			pairs[mrpt::Clock::toDouble(p->timestamp)] = !p->imageLeft.isExternallyStored() &&
				p->hasImageRight && !p->imageRight.isExternallyStored();
	return pairs;
}
}  // namespace

TEST(RecordingReplayClock, NowDeliversTheFirstFrameAtOnceAndKeepsTheRecordedIntervals)
{
	RecordingReplayClock clock(RecordingReplayClock::Mode::Now);
	const auto first = clock.schedule(1000.0, 5000.0);
	ASSERT_TRUE(first);
	EXPECT_EQ(first->wait, 0.0);
	EXPECT_DOUBLE_EQ(first->stamp, 5000.0);
	// Read 10 ms later, recorded 0.4 s later: due in 0.39 s, re-stamped.
	const auto second = clock.schedule(1000.4, 5000.01);
	ASSERT_TRUE(second);
	EXPECT_NEAR(second->wait, 0.39, 1e-9);
	EXPECT_NEAR(second->stamp, 5000.4, 1e-9);
	// Read after it was due (the reader fell behind): at once, never skipped.
	const auto third = clock.schedule(1000.8, 5001.5);
	ASSERT_TRUE(third);
	EXPECT_EQ(third->wait, 0.0);
	EXPECT_NEAR(third->stamp, 5000.8, 1e-9);
}

TEST(RecordingReplayClock, RecordedDeliversAtTheStampsAndSkipsFramesFromBeforeTheCameraOpened)
{
	RecordingReplayClock clock(RecordingReplayClock::Mode::Recorded);
	EXPECT_FALSE(clock.schedule(1000.0, 1000.5));  // 0.5 s overdue: before it opened
	EXPECT_FALSE(clock.schedule(1000.49, 1000.5));	// 10 ms: it would hold the others back
	const auto slightly = clock.schedule(1000.498, 1000.5);
	ASSERT_TRUE(slightly);	// 2 ms overdue: at once, its own stamp
	EXPECT_EQ(slightly->wait, 0.0);
	EXPECT_DOUBLE_EQ(slightly->stamp, 1000.498);
	const auto ahead = clock.schedule(1000.9, 1000.5);
	ASSERT_TRUE(ahead);
	EXPECT_NEAR(ahead->wait, 0.4, 1e-9);
	EXPECT_DOUBLE_EQ(ahead->stamp, 1000.9);
}

TEST(Live, AStereoCameraReplayedByCCameraSensorFeedsTheStereoLandmarksLive)
{
	TempDir dir;
	const unsigned short laser = freePort(), odo = freePort();
	const std::string out = dir.file("live"), replay = dir.file("replay"),
					  prefix = dir.file("emu");
	const std::string config = std::string(FEATLOC_SOURCE_DIR) + "/configs/live-stereo-emulator.ini";
	const std::string devices = " --set LASER:PORT_DIR=" + std::to_string(laser) +
		" --set ODOMETRY:port=" + std::to_string(odo) +
		" --set CAMERA:rawlog_file=" + shellQuote(prefix + ".camera.rawlog");
	// Moon et al.'s lab scene: 2 m in about 6 s, the camera at 2.5 Hz.
	const CommandResult r = runCommand(shellQuote(FEATLOC_SIM_EXE) + " " +
		shellQuote(std::string(FEATLOC_SOURCE_DIR) + "/worlds/moon-lab.ini") + " --out " +
		shellQuote(prefix) + " --serve -q --laser-port " + std::to_string(laser) +
		" --odometry-port " + std::to_string(odo) + " > " + shellQuote(prefix + ".out") +
		" 2>&1 & emu=$!; " + waitForEmulator(prefix + ".out") + shellQuote(FEATLOC_LIVE_EXE) +
		" " + shellQuote(config) +
		" -q" + devices + " --duration 5 --out " + shellQuote(out) +
		" --set Evaluation:ground_truth=" + shellQuote(prefix + ".served.gt.txt") +
		"; code=$?; kill -TERM $emu; wait $emu; echo exit=$code; cat " +
		shellQuote(prefix + ".out"));
	ASSERT_NE(r.output.find("exit=0"), std::string::npos) << r.output;

	const auto s = readJson(out + "/summary.json");
	const auto& camera = s["live"]["sensors"][2];
	ASSERT_EQ(camera["driver"], "CCameraSensor") << s.dump(1);
	// 12 or 13 pairs are due in 5 s; the first ones, captured before the
	// camera opened its recording, are skipped as a camera would never see them.
	EXPECT_GE(camera["received"].get<size_t>(), 9u) << camera.dump();
	EXPECT_LE(camera["replay_skipped"].get<size_t>(), 3u) << camera.dump();
	EXPECT_EQ(camera["late"], 0);
	EXPECT_EQ(s["live"]["late_observations"], 0);
	// The stereo landmarks ran on every pair passed on and the EKF used them.
	const auto& stereo = s["stereo_landmarks"];
	EXPECT_EQ(stereo["pairs_processed"], camera["passed_on"]);
	EXPECT_GT(stereo["features_selected"].get<size_t>(), 50u) << stereo.dump();
	EXPECT_GT(stereo["observations_used"].get<size_t>(), 20u) << stereo.dump();
	EXPECT_LT(s["evaluation"]["ate_m"]["rmse"].get<double>(), 0.05) << s.dump(1);

	// Every pair passed on is in live.rawlog with its images in it, at the
	// stamp the emulator gave it (delivered when due, not re-stamped).
	const auto recorded = stereoPairs(out + "/live.rawlog");
	const auto served = stereoPairs(prefix + ".camera.rawlog");
	EXPECT_EQ(recorded.size(), camera["passed_on"].get<size_t>());
	for (const auto& [t, inMemory] : recorded)
	{
		EXPECT_TRUE(inMemory) << "pair at " << t;
		EXPECT_EQ(served.count(t), 1u) << "pair at " << t << " not served so";
	}

	// featloc-run replays the recording to the same poses.
	const CommandResult rr = runCommand(shellQuote(FEATLOC_RUN_EXE) + " " + shellQuote(config) +
		" " + shellQuote(out + "/live.rawlog") + " -q --out " + shellQuote(replay) + devices);
	ASSERT_EQ(rr.exitCode, 0) << rr.output;
	const auto a = dataRows(out + "/trajectory.tum"), b = dataRows(replay + "/trajectory.tum");
	ASSERT_FALSE(a.empty());
	EXPECT_EQ(a, b);
}
