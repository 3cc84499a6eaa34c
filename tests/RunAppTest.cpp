// App-level tests: featloc-run and featloc-eval as a user runs them, on real
// MRPT logs (Debian mrpt-common) and on generated ones.
#include <gtest/gtest.h>
#include <mrpt/obs/CObservationRobotPose.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/random/RandomGenerators.h>
#include <mrpt/core/bits_math.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "featloc/eval/TrajectoryFile.h"
#include "featloc/io/MatchTableFile.h"
#include "featloc/io/RawlogReader.h"
#include "featloc/registerClasses.h"
#include "support/CommandRunner.h"
#include "support/JsonFile.h"
#include "support/TempDir.h"
#include "support/TextFile.h"
#include "support/SyntheticRoom.h"
#include "support/TestRawlog.h"

using namespace featloc;
using featloc::test::CommandResult;
using featloc::test::readJson;
using featloc::test::runCommand;
using featloc::test::shellQuote;
using featloc::test::TempDir;
using featloc::test::readText;
using featloc::test::TestRawlog;
using mrpt::poses::CPose2D;

namespace
{
const std::string kRun = FEATLOC_RUN_EXE;
const std::string kEval = FEATLOC_EVAL_EXE;
const std::string kConfig = std::string(FEATLOC_SOURCE_DIR) + "/config.ini";
const std::string kDatasets = MRPT_DATASETS_DIR;
const std::string kSimul =
	kDatasets + "/graphslam-engine-demos/action_observations_map/simul.rawlog";
const std::string kMalaga =
	kDatasets + "/2006-01ENE-21-SENA_Telecom Faculty_one_loop_only.rawlog";

CommandResult featlocRun(const std::string& args)
{
	return runCommand(shellQuote(kRun) + " " + args + " -q");
}

size_t dataRows(const std::string& file)
{
	std::ifstream in(file);
	std::string line;
	size_t n = 0;
	while (std::getline(in, line))
		if (!line.empty() && line[0] != '#') n++;
	return n;
}

/** Pose observations in a rawlog, and entries. */
std::pair<size_t, size_t> countPoses(const std::string& rawlog, const std::string& label)
{
	RawlogReader reader(rawlog);
	RawlogEntry e;
	size_t poses = 0, entries = 0;
	auto isPose = [&](const mrpt::obs::CObservation::Ptr& o) {
		return std::dynamic_pointer_cast<mrpt::obs::CObservationRobotPose>(o) &&
			o->sensorLabel == label;
	};
	while (reader.next(e))
	{
		entries++;
		if (auto sf = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(e.object))
		{
			for (const auto& o : *sf) poses += isPose(o);
		}
		else if (auto o = std::dynamic_pointer_cast<mrpt::obs::CObservation>(e.object))
		{
			poses += isPose(o);
		}
	}
	return {poses, entries};
}
/** `log` with every scan replaced by the exact scan of `room` from the
 * log's path (the scan's label, time and sensor pose kept), written to
 * `file`. */
void writeWithScansOf(TestRawlog log, const featloc::test::SyntheticRoom& room,
	const std::string& file)
{
	log.editScan = [&](size_t k, mrpt::obs::CObservation2DRangeScan& s) {
		auto c = room.scan(log.path(log.scanPeriod * static_cast<double>(k)));
		c->sensorLabel = s.sensorLabel;
		c->timestamp = s.timestamp;
		c->sensorPose = s.sensorPose;
		s = *c;
	};
	log.write(file);
}
/** featloc-run's arguments for PCM's matcher chain over `rawlog` with
 * every scan a keyframe (each match against the previous scan). */
std::string pcmChainEveryScanArgs(const std::string& rawlog)
{
	return shellQuote(kConfig) + " " + shellQuote(rawlog) +
		" --set ScanMatcher:class=PcmFeatureMatcher --set Pipeline:estimator=matcher"
		" --set Pipeline:keyframe_distance=0 --set Pipeline:keyframe_angle_DEG=0"
		" --set Output:write_scene=false";
}
}  // namespace

TEST(FeatlocRun, HelpListsTheSetOption)
{
	const CommandResult r = runCommand(shellQuote(kRun) + " --help");
	EXPECT_EQ(r.exitCode, 0) << r.output;
	EXPECT_NE(r.output.find("--set"), std::string::npos) << r.output;
	EXPECT_NE(r.output.find("SECTION:KEY=VALUE"), std::string::npos);
}

TEST(FeatlocRun, SimulatedLogMatcherBeatsOdometryAgainstExactGroundTruth)
{
	registerClasses();
	TempDir dir;
	const std::string gt = kSimul + ".GT.txt";
	const std::string common = shellQuote(kConfig) + " " + shellQuote(kSimul) +
		" --set Evaluation:ground_truth=" + shellQuote(gt);
	const CommandResult m =
		featlocRun(common + " --out " + shellQuote(dir.file("matcher")));
	ASSERT_EQ(m.exitCode, 0) << m.output;
	const CommandResult o = featlocRun(
		common + " --out " + shellQuote(dir.file("odometry")) +
		" --set Pipeline:estimator=odometry");
	ASSERT_EQ(o.exitCode, 0) << o.output;

	const auto sm = readJson(dir.file("matcher/summary.json"));
	const auto so = readJson(dir.file("odometry/summary.json"));
	EXPECT_EQ(sm["status"], "ok");
	EXPECT_EQ(sm["counts"]["scans"], 1733);
	EXPECT_EQ(sm["matcher"], "featloc::IcpMatcher");
	EXPECT_EQ(so["matcher"], nullptr);
	const double ateMatcher = sm["evaluation"]["ate_m"]["rmse"];
	const double ateOdometry = so["evaluation"]["ate_m"]["rmse"];
	// Measured 0.21 m (matcher, 1 m keyframes) and 7.5 m (odometry, which
	// drifts in heading) on this 200 m, 5 cm-noise simulated log.
	EXPECT_LT(ateMatcher, 0.35);
	EXPECT_GT(ateOdometry, 5 * ateMatcher);
	EXPECT_EQ(sm["evaluation"]["associated"], 1733);

	for (const char* f : {"trajectory.tum", "poses_cov.txt", "estimated.rawlog",
			 "map.3Dscene", "summary.json", "config_used.ini", "trajectory.png"})
		EXPECT_TRUE(std::filesystem::exists(dir.file(std::string("matcher/") + f)))
			<< f;
	EXPECT_EQ(dataRows(dir.file("matcher/trajectory.tum")), 1733u);
	EXPECT_EQ(dataRows(dir.file("matcher/poses_cov.txt")), 1733u);

	// featloc-eval agrees with the run's own evaluation.
	const CommandResult ev = runCommand(
		shellQuote(kEval) + " " + shellQuote(gt) + " " +
		shellQuote(dir.file("matcher/trajectory.tum")) + " --json");
	ASSERT_EQ(ev.exitCode, 0) << ev.output;
	EXPECT_NEAR(nlohmann::json::parse(ev.output)["ate_m"]["rmse"].get<double>(),
		ateMatcher, 1e-9);
}

// config_used.ini is a configuration that runs again from any folder: its
// relative paths (the shipped config.ini's bundled log and ground truth)
// are written resolved, comments kept, and the second run gives the same
// trajectory.
TEST(FeatlocRun, ConfigUsedRunsAgainFromAnotherFolder)
{
	TempDir dir;
	const CommandResult first = featlocRun(shellQuote(kConfig) + " --out " +
		shellQuote(dir.file("first")) + " --set Pipeline:estimator=odometry" +
		" --set Output:write_scene=false --set Output:write_rawlog=false");
	ASSERT_EQ(first.exitCode, 0) << first.output;
	const std::string used = readText(dir.file("first/config_used.ini"));
	const std::string root = std::string(FEATLOC_SOURCE_DIR);
	EXPECT_NE(used.find("rawlog = " + std::filesystem::path(root + "/rawlogs/mrpt-simul/simul.rawlog")
									 .lexically_normal()
									 .string() +
				"  // bundled default log"),
		std::string::npos)
		<< used.substr(0, 800);
	EXPECT_NE(used.find("ground_truth = /"), std::string::npos);

	const CommandResult again = runCommand("cd " + shellQuote(dir.path().string()) + " && " +
		shellQuote(kRun) + " " + shellQuote(dir.file("first/config_used.ini")) + " --out " +
		shellQuote(dir.file("again")) + " -q");
	ASSERT_EQ(again.exitCode, 0) << again.output;
	EXPECT_EQ(readText(dir.file("first/trajectory.tum")), readText(dir.file("again/trajectory.tum")));
}

TEST(FeatlocRun, EstimatedRawlogHoldsInputAndOnePosePerScan)
{
	registerClasses();
	TempDir dir;
	const CommandResult r = featlocRun(
		shellQuote(kConfig) + " " + shellQuote(kMalaga) + " --out " +
		shellQuote(dir.path().string()));
	ASSERT_EQ(r.exitCode, 0) << r.output;
	const auto [poses, entries] =
		countPoses(dir.file("estimated.rawlog"), "featloc_estimate");
	EXPECT_EQ(poses, 225u);
	EXPECT_EQ(entries, 449u);  // same entries as the input, poses inside SFs

	// MRPT's own tool reads it too.
	const CommandResult info = runCommand(
		"rawlog-edit --info -i " + shellQuote(dir.file("estimated.rawlog")));
	EXPECT_EQ(info.exitCode, 0) << info.output;
	EXPECT_NE(info.output.find("featloc_estimate"), std::string::npos) << info.output;
}

TEST(FeatlocRun, MalagaLogStaysCloseToMrptIcpSlam)
{
	registerClasses();
	TempDir dir;
	// MRPT's icp-slam on the same log, with its demo configuration (no GUI).
	std::ifstream demo("/usr/share/mrpt/config_files/icp-slam/icp-slam_demo_classic.ini");
	ASSERT_TRUE(demo) << "mrpt-apps config files missing";
	std::stringstream ss;
	ss << demo.rdbuf();
	std::string ini = ss.str();
	const std::string gui = "SHOW_PROGRESS_3D_REAL_TIME=1";
	ini.replace(ini.find(gui), gui.size(), "SHOW_PROGRESS_3D_REAL_TIME=0");
	std::ofstream(dir.file("icp.ini")) << ini;
	const CommandResult slam = runCommand(
		"cd " + shellQuote(dir.path().string()) + " && icp-slam icp.ini " +
		shellQuote(kMalaga) + " < /dev/null");
	ASSERT_EQ(slam.exitCode, 0) << slam.output.substr(0, 2000);
	const std::string slamPath = dir.file("LOG_ICP-SLAM/log_estimated_path.txt");

	const CommandResult r = featlocRun(
		shellQuote(kConfig) + " " + shellQuote(kMalaga) + " --out " +
		shellQuote(dir.file("featloc")));
	ASSERT_EQ(r.exitCode, 0) << r.output;
	const Trajectory ours = TrajectoryFile::read(dir.file("featloc/trajectory.tum"));
	ASSERT_EQ(ours.poses.size(), 225u);	// one pose per scan of the log

	// icp-slam logs one pose per action/observation pair: its row k is the
	// robot at our scan k+1 (the log starts with a lone sensory frame).
	std::ifstream in(slamPath);
	std::vector<double> dev;
	double idx = 0, x = 0, y = 0, phi = 0;
	while (in >> idx >> x >> y >> phi)
	{
		const auto& p = ours.poses.at(static_cast<size_t>(idx) + 1).pose;
		dev.push_back(std::hypot(p.x - x, p.y - y));
	}
	ASSERT_EQ(dev.size(), 224u);
	double mean = 0, max = 0;
	for (double d : dev)
	{
		mean += d / static_cast<double>(dev.size());
		max = std::max(max, d);
	}
	// Measured: mean 0.14 m, max 0.62 m over the ~60 m loop.
	EXPECT_LT(mean, 0.3);
	EXPECT_LT(max, 1.0);
}

TEST(FeatlocRun, Format2LogWithExactGroundTruth)
{
	registerClasses();
	TempDir dir;
	TestRawlog log;
	log.scans = 40;
	log.observationsOnly = true;
	const auto times = log.write(dir.file("f2.rawlog"));
	{
		std::ofstream gt(dir.file("gt.txt"));
		gt.precision(12);
		for (size_t k = 0; k < times.size(); k++)
		{
			const auto p = log.path(log.scanPeriod * static_cast<double>(k));
			gt << times[k] << " " << p.x() << " " << p.y() << " " << p.phi() << "\n";
		}
	}
	// The run starts at the true initial pose; noise-free scans.
	const auto p0 = log.path(0);
	const CommandResult r = featlocRun(
		shellQuote(kConfig) + " " + shellQuote(dir.file("f2.rawlog")) +
		" --out " + shellQuote(dir.file("out")) +
		" --set Evaluation:ground_truth=" + shellQuote(dir.file("gt.txt")) +
		" --set Output:write_scene=false");
	ASSERT_EQ(r.exitCode, 0) << r.output;
	const auto s = readJson(dir.file("out/summary.json"));
	EXPECT_EQ(s["counts"]["scans"], 40);
	EXPECT_GT(s["counts"]["odometry_readings"].get<int>(), 100);
	EXPECT_EQ(s["counts"]["steps_without_odometry"], 0);
	EXPECT_LT(s["evaluation"]["ate_m"]["rmse"].get<double>(), 0.01);
	EXPECT_LT(s["evaluation"]["rpe_rotation"]["max"].get<double>(), 0.2);  // deg
	(void)p0;
	EXPECT_FALSE(std::filesystem::exists(dir.file("out/map.3Dscene")));
	const auto [poses, entries] = countPoses(dir.file("out/estimated.rawlog"), "featloc_estimate");
	EXPECT_EQ(poses, 40u);
}

TEST(FeatlocRun, WithoutOdometryTheGuessIsTheEstimatesRecentVelocity)
{
	registerClasses();
	TempDir dir;
	TestRawlog log;
	log.scans = 40;
	log.observationsOnly = true;
	log.odometry = false;
	// A wheeled robot on an arc of 2.2 m at 1.32 m/s and 34 deg/s: 13 cm
	// and 3.4 deg between scans 0.1 s apart.
	log.path = [](double t) {
		const double w = 0.6, r = 2.2;
		return CPose2D(-0.8 + r * std::sin(w * t), 0.3 - r * std::cos(w * t), w * t);
	};
	log.write(dir.file("noodo.rawlog"));
	auto run = [&](const std::string& prior) {
		const std::string out = dir.file("out-" + prior);
		const CommandResult r = featlocRun(shellQuote(kConfig) + " " +
			shellQuote(dir.file("noodo.rawlog")) + " --out " + shellQuote(out) +
			" --set Odometry:no_odometry_prior=" + prior + " --set Output:write_scene=false");
		EXPECT_EQ(r.exitCode, 0) << r.output;
		return out;
	};
	// Median distance between the matcher's guess and its estimate.
	auto guessOff = [](const std::string& out) {
		std::vector<double> d;
		for (const auto& row : MatchTableFile::read(out + "/matches.txt"))
			d.push_back(std::hypot(row.guess.x - row.estimate.x, row.guess.y - row.estimate.y));
		std::sort(d.begin(), d.end());
		return d.empty() ? 1e9 : d[d.size() / 2];
	};
	const std::string zero = run("zero"), velocity = run("constant_velocity");
	const auto s = readJson(velocity + "/summary.json");
	EXPECT_EQ(s["counts"]["steps_without_odometry"], 39);
	// The window (0.5 s) fills after 5 scans: from then on every step.
	EXPECT_GE(s["counts"]["steps_with_constant_velocity_prior"].get<int>(), 33);
	EXPECT_EQ(readJson(zero + "/summary.json")["counts"]["steps_with_constant_velocity_prior"], 0);
	// Zero motion guesses the 13 cm step wrong by 13 cm; the velocity
	// guesses it to well under a centimetre (exact scans, constant twist).
	EXPECT_GT(guessOff(zero), 0.10);
	EXPECT_LT(guessOff(velocity), 0.01);
}

TEST(FeatlocRun, BadInputGivesAClearMessageAndNonZeroExit)
{
	registerClasses();
	TempDir dir;
	TestRawlog nanLog;
	nanLog.scans = 5;
	nanLog.editScan = [](size_t k, mrpt::obs::CObservation2DRangeScan& s) {
		if (k == 3) s.setScanRange(7, std::nanf(""));
	};
	nanLog.write(dir.file("nan.rawlog"));
	std::ofstream(dir.file("typo.ini")) << "[ScanMatcher.IcpMatcher]\nmaxIteratons = 5\n";
	std::ofstream(dir.file("class.ini")) << "[ScanMatcher]\nclass = featloc::Nope\n";
	std::ofstream(dir.file("garbage.rawlog")) << "hello\n";

	struct Case
	{
		std::string args;
		int exitCode;
		std::vector<std::string> expected;
	};
	const std::string out = " --out " + shellQuote(dir.file("o"));
	const std::vector<Case> cases = {
		{shellQuote(kConfig) + " " + shellQuote(dir.file("missing.rawlog")) + out, 1,
			{"missing.rawlog", "does not exist"}},
		{shellQuote(dir.file("missing.ini")), 2, {"missing.ini", "does not exist"}},
		{shellQuote(dir.file("typo.ini")) + " " + shellQuote(kMalaga) + out, 2,
			{"typo.ini:2", "maxIteratons", "did you mean 'maxIterations'"}},
		{shellQuote(dir.file("class.ini")) + " " + shellQuote(kMalaga) + out, 2,
			{"class.ini:2", "featloc::Nope", "featloc::IcpMatcher"}},
		{shellQuote(kConfig) + " " + shellQuote(dir.file("nan.rawlog")) + out, 1,
			{"nan.rawlog", "entry #6", "beam 7", "nan"}},
		{shellQuote(kConfig) + " " + shellQuote(dir.file("garbage.rawlog")) + out, 1,
			{"garbage.rawlog", "entry #0", "corrupt"}},
		{shellQuote(kConfig) + " --set Pipeline:estimator=kalman" + out, 2,
			{"--set Pipeline:estimator=kalman", "known: odometry, matcher, ekf, featloc::EkfEstimator"}},
		{shellQuote(kConfig) + " --set Pipelineestimator=odometry" + out, 2,
			{"SECTION:KEY=VALUE"}},
		{"", 2, {"missing CONFIG"}},
		{"a b c", 2, {"too many arguments"}},
	};
	for (const auto& c : cases)
	{
		const CommandResult r = featlocRun(c.args);
		EXPECT_EQ(r.exitCode, c.exitCode) << c.args << "\n" << r.output;
		for (const auto& e : c.expected)
			EXPECT_NE(r.output.find(e), std::string::npos)
				<< "'" << e << "' not in the output of " << c.args << ":\n"
				<< r.output;
		EXPECT_EQ(r.output.find("terminate called"), std::string::npos) << r.output;
	}
}

TEST(FeatlocRun, TruncatedRawlogKeepsWhatWasWritten)
{
	registerClasses();
	TempDir dir;
	TestRawlog log;
	log.scans = 30;
	log.compress = false;
	log.write(dir.file("full.rawlog"));
	const auto size = std::filesystem::file_size(dir.file("full.rawlog"));
	{
		std::ifstream in(dir.file("full.rawlog"), std::ios::binary);
		std::string data(size * 2 / 3, '\0');
		in.read(data.data(), static_cast<std::streamsize>(data.size()));
		std::ofstream(dir.file("cut.rawlog"), std::ios::binary) << data;
	}
	const CommandResult r = featlocRun(
		shellQuote(kConfig) + " " + shellQuote(dir.file("cut.rawlog")) +
		" --out " + shellQuote(dir.file("out")));
	EXPECT_EQ(r.exitCode, 1) << r.output;
	EXPECT_NE(r.output.find("truncated"), std::string::npos) << r.output;
	EXPECT_NE(r.output.find("entry #"), std::string::npos) << r.output;
	// The scans before the damage are in every output.
	const size_t rows = dataRows(dir.file("out/trajectory.tum"));
	EXPECT_GE(rows, 15u);
	EXPECT_LT(rows, 30u);
	const auto s = readJson(dir.file("out/summary.json"));
	EXPECT_EQ(s["status"], "error");
	EXPECT_NE(s["error"].get<std::string>().find("truncated"), std::string::npos);
	EXPECT_EQ(s["counts"]["scans"].get<size_t>(), rows);
	EXPECT_EQ(countPoses(dir.file("out/estimated.rawlog"), "featloc_estimate").first, rows);
}

TEST(FeatlocEval, PlotAndTextReport)
{
	TempDir dir;
	std::ofstream gt(dir.file("gt.txt")), est(dir.file("est.tum"));
	for (int i = 0; i < 50; i++)
	{
		const double t = i * 0.1, a = i * 0.1;
		gt << t << " " << std::cos(a) << " " << std::sin(a) << " " << a + M_PI / 2 << "\n";
		est << t << " " << std::cos(a) + 0.01 << " " << std::sin(a) << " 0 0 0 "
			<< std::sin((a + M_PI / 2) / 2) << " " << std::cos((a + M_PI / 2) / 2) << "\n";
	}
	gt.close();
	est.close();
	const CommandResult r = runCommand(
		shellQuote(kEval) + " " + shellQuote(dir.file("gt.txt")) + " " +
		shellQuote(dir.file("est.tum")) + " --plot " + shellQuote(dir.file("p.png")));
	ASSERT_EQ(r.exitCode, 0) << r.output;
	EXPECT_NE(r.output.find("ATE translation"), std::string::npos) << r.output;
	EXPECT_NE(r.output.find("50 associated"), std::string::npos) << r.output;
	EXPECT_GT(std::filesystem::file_size(dir.file("p.png")), 5000u);

	const CommandResult bad = runCommand(
		shellQuote(kEval) + " " + shellQuote(dir.file("gt.txt")) + " " +
		shellQuote(dir.file("nope.tum")));
	EXPECT_EQ(bad.exitCode, 1);
	EXPECT_NE(bad.output.find("nope.tum' does not exist"), std::string::npos) << bad.output;
}

// --paired-with: two estimates of one run compared step by step. B is A
// with a jump of 30 cm in five steps (and back the step after): ten steps
// off for B alone, and A's RPE lower on average.
TEST(FeatlocEval, PairedWithComparesTwoEstimatesStepByStep)
{
	TempDir dir;
	std::ofstream gt(dir.file("gt.txt")), a(dir.file("a.txt")), b(dir.file("b.txt"));
	for (int i = 0; i < 200; i++)
	{
		const double t = i * 0.1, x = 0.05 * i, noise = 0.002 * std::sin(1.7 * i);
		gt << t << " " << x << " 0 0\n";
		a << t << " " << x + noise << " 0 0\n";
		b << t << " " << x + noise + (i % 40 == 20 ? 0.3 : 0.0) << " 0 0\n";
	}
	gt.close();
	a.close();
	b.close();
	const std::string common = shellQuote(kEval) + " " + shellQuote(dir.file("gt.txt")) + " " +
		shellQuote(dir.file("a.txt")) + " --paired-with " + shellQuote(dir.file("b.txt"));
	const CommandResult r = runCommand(common + " -j");
	ASSERT_EQ(r.exitCode, 0) << r.output;
	const auto j = nlohmann::json::parse(r.output);
	const auto& p = j["paired"];
	EXPECT_EQ(p["steps"], 199);
	EXPECT_EQ(p["off_only_this"], 0);
	EXPECT_EQ(p["off_only_other"], 10);
	EXPECT_LT(p["mcnemar_p"].get<double>(), 0.01);
	// Mean difference: -0.3 m x 10 steps / 199.
	EXPECT_NEAR(p["rpe_trans_mean_diff_m"].get<double>(), -3.0 / 199, 1e-4);
	EXPECT_LT(p["ci95_m"][1].get<double>(), 0.0);
	const CommandResult text = runCommand(common);
	ASSERT_EQ(text.exitCode, 0) << text.output;
	EXPECT_NE(text.output.find("only this 0, only the other 10"), std::string::npos) << text.output;
	const CommandResult missing = runCommand(shellQuote(kEval) + " " + shellQuote(dir.file("gt.txt")) +
		" " + shellQuote(dir.file("a.txt")) + " --paired-with " + shellQuote(dir.file("nope.txt")));
	EXPECT_EQ(missing.exitCode, 1);
	EXPECT_NE(missing.output.find("nope.txt' does not exist"), std::string::npos) << missing.output;
}

TEST(FeatlocRun, ShippedSimulatedScenesAgainstTheirGroundTruth)
{
	registerClasses();
	TempDir dir;
	const std::string sim = std::string(FEATLOC_SOURCE_DIR) + "/rawlogs/sim/";
	auto ate = [&](const std::string& scene, const std::string& estimator) {
		const CommandResult r = featlocRun(
			shellQuote(kConfig) + " " + shellQuote(sim + scene + ".rawlog") +
			" --out " + shellQuote(dir.file(scene + "-" + estimator)) +
			" --set Pipeline:estimator=" + estimator +
			" --set Evaluation:ground_truth=" + shellQuote(sim + scene + ".gt.txt") +
			" --set Output:write_scene=false --set Output:write_rawlog=false");
		EXPECT_EQ(r.exitCode, 0) << r.output;
		const auto s = readJson(dir.file(scene + "-" + estimator + "/summary.json"));
		EXPECT_EQ(s["evaluation"]["associated"], s["counts"]["scans"]);
		return s["evaluation"]["ate_m"]["rmse"].get<double>();
	};
	// Documented in rawlogs/README.md: odometry drifts 0.18 / 0.12 m, the
	// ICP baseline gets 0.13 / 0.025 m on the static scenes.
	const double officeOdo = ate("office", "odometry"), officeIcp = ate("office", "matcher");
	const double labOdo = ate("lab", "odometry"), labIcp = ate("lab", "matcher");
	EXPECT_GT(officeOdo, 0.1);
	EXPECT_LT(officeIcp, officeOdo);
	EXPECT_GT(labOdo, 0.08);
	EXPECT_LT(labIcp, 0.05);
}

TEST(FeatlocBench, PaperProtocolTableOnASimulatedScene)
{
	TempDir dir;
	const std::string sim = std::string(FEATLOC_SOURCE_DIR) + "/rawlogs/sim/";
	const CommandResult r = runCommand(
		shellQuote(FEATLOC_BENCH_EXE) + " " + shellQuote(kConfig) + " " +
		shellQuote(sim + "lab.rawlog") + " -g " + shellQuote(sim + "lab.gt.txt") +
		" --max-pairs 40 --header -j " + shellQuote(dir.file("b.json")));
	ASSERT_EQ(r.exitCode, 0) << r.output;
	EXPECT_NE(r.output.find("| lab.rawlog | featloc::PcmFeatureMatcher | 40 |"),
		std::string::npos)
		<< r.output;
	EXPECT_NE(r.output.find("| lab.rawlog | featloc::IcpMatcher | 40 |"), std::string::npos);
	const auto j = readJson(dir.file("b.json"));
	ASSERT_EQ(j["results"].size(), 2u);
	// Both matchers recover the lab's motions to a few millimetres from
	// +-0.3 m / +-10 deg initial errors (2.5 cm range noise).
	for (const auto& m : j["results"])
	{
		EXPECT_LT(m["mae_x_m"].get<double>(), 0.01) << m["matcher"];
		EXPECT_LT(m["mae_yaw_deg"].get<double>(), 0.2) << m["matcher"];
		EXPECT_EQ(m["failures"], 0) << m["matcher"];
	}
	// Without ground truth the reference matcher is required.
	const CommandResult noGt = runCommand(
		shellQuote(FEATLOC_BENCH_EXE) + " " + shellQuote(kConfig) + " " +
		shellQuote(sim + "lab.rawlog"));
	EXPECT_EQ(noGt.exitCode, 2);
	EXPECT_NE(noGt.output.find("--reference-matcher"), std::string::npos) << noGt.output;
}

TEST(FeatlocBench, NunezProtocolWithMatcherVariantsSideBySide)
{
	// The CF-IDC paper's protocol on a short piece of the hall with people:
	// same-place pairs, a random motion of mean 1 m and 15 deg applied.
	TempDir dir;
	const std::string hall = std::string(FEATLOC_SOURCE_DIR) + "/worlds/hall-people.ini";
	const CommandResult sim = runCommand(shellQuote(FEATLOC_SIM_EXE) + " " + shellQuote(hall) +
		" --out " + shellQuote(dir.file("hall")) + " --set Simulation:duration=8 -q");
	ASSERT_EQ(sim.exitCode, 0) << sim.output;
	const std::string common = shellQuote(FEATLOC_BENCH_EXE) + " " + shellQuote(kConfig) + " " +
		shellQuote(dir.file("hall.rawlog")) + " -g " + shellQuote(dir.file("hall.gt.txt")) +
		" --perturbation gaussian --perturb-xy 0.05 --perturb-yaw-deg 5 -q";
	const CommandResult r = runCommand(common +
		" --apply-motion 0.7071,0.7071,15 --header -j " + shellQuote(dir.file("b.json")) +
		" -m 'IDC as published=featloc::IdcMatcher{final_phase=idc},featloc::CfIdcMatcher'");
	ASSERT_EQ(r.exitCode, 0) << r.output;
	EXPECT_NE(r.output.find("| hall.rawlog | IDC as published | 40 |"), std::string::npos) << r.output;
	EXPECT_NE(r.output.find("| hall.rawlog | featloc::CfIdcMatcher | 40 |"), std::string::npos)
		<< r.output;
	const auto j = readJson(dir.file("b.json"));
	EXPECT_NEAR(j["applied_motion"]["yaw_deg"].get<double>(), 15, 1e-9);
	ASSERT_EQ(j["results"].size(), 2u);
	for (const auto& m : j["results"])
	{
		// The moved scans are recovered to millimetres from 50 mm / 5 deg.
		EXPECT_EQ(m["failures"], 0) << m["matcher"];
		EXPECT_LT(m["mae_x_m"].get<double>(), 0.006) << m["matcher"];
		EXPECT_LT(m["mae_yaw_deg"].get<double>(), 0.06) << m["matcher"];
	}

	// A misspelled override names the key and the one meant; a malformed
	// motion is a usage error.
	const CommandResult typo =
		runCommand(common + " -m 'featloc::CfIdcMatcher{segment_gat=0}'");
	EXPECT_EQ(typo.exitCode, 2);
	EXPECT_NE(typo.output.find("segment_gat"), std::string::npos) << typo.output;
	EXPECT_NE(typo.output.find("did you mean 'segment_gate'"), std::string::npos) << typo.output;
	const CommandResult motion = runCommand(common + " --apply-motion 1,x,15");
	EXPECT_EQ(motion.exitCode, 2);
	EXPECT_NE(motion.output.find("--apply-motion: 'x' is not a number"), std::string::npos)
		<< motion.output;
	const CommandResult braces = runCommand(common + " -m 'featloc::IdcMatcher{final_phase=idc'");
	EXPECT_EQ(braces.exitCode, 2);
	EXPECT_NE(braces.output.find("unbalanced"), std::string::npos) << braces.output;
}

// summary.json counts the failed matches by kind; a coarse search that
// demands 99% of the points on the reference fails every match for lack of
// overlap, and the pipeline then uses odometry for each (the estimator
// keeps its prediction on a flagged failure).
TEST(FeatlocRun, FailedMatchesAreCountedByKindInTheSummary)
{
	registerClasses();
	TempDir dir;
	const CommandResult r = featlocRun(shellQuote(kConfig) + " " + shellQuote(kMalaga) + " --out " +
		shellQuote(dir.file("out")) + " --set ScanMatcher.IcpMatcher:coarse_search=true" +
		" --set ScanMatcher.IcpMatcher:coarse_min_score=0.99");
	ASSERT_EQ(r.exitCode, 0) << r.output;
	const auto s = readJson(dir.file("out/summary.json"));
	const size_t matches = s["counts"]["matches"], failures = s["counts"]["match_failures"];
	EXPECT_GT(matches, 100u);
	EXPECT_EQ(failures, matches);
	EXPECT_EQ(s["counts"]["match_failures_by_kind"]["no_overlap"], failures);
	EXPECT_EQ(s["counts"]["fallbacks_to_odometry"], failures);
	EXPECT_NE(s["failure_examples"][0].get<std::string>().find("coarse_min_score"), std::string::npos);

	TempDir plain;
	const CommandResult p = featlocRun(shellQuote(kConfig) + " " + shellQuote(kMalaga) + " --out " +
		shellQuote(plain.file("out")));
	ASSERT_EQ(p.exitCode, 0) << p.output;
	const auto sp = readJson(plain.file("out/summary.json"));
	size_t byKind = 0;
	for (const auto& [kind, n] : sp["counts"]["match_failures_by_kind"].items()) byKind += n.get<size_t>();
	EXPECT_EQ(byKind, sp["counts"]["match_failures"].get<size_t>());
	EXPECT_EQ(sp["counts"]["ambiguous_matches_used"], 0);  // the coarse search is off by default
	EXPECT_EQ(sp["counts"]["matcher_fallbacks"], 0);  // ICP has none
	EXPECT_EQ(sp["counts"]["matches_with_segments_dropped_by_residuals"], 0);	 // CF-IDC's only
	EXPECT_EQ(sp["counts"]["segments_dropped_by_residuals"], 0);
}

// On the bundled log CF-IDC's guess gate rejects good matches where the
// odometry was read long before the scan; the scans overrule some of them.
// Each is a success marked "overruled" in matches.txt, with the gate's
// reason and the evidence, and summary.json counts them. (CF-IDC's own
// matches: without its IDC fallback, which would remake the rejections.)
TEST(FeatlocRun, OverruledGuessGatesAreMarkedAndCounted)
{
	TempDir dir;
	const std::string cfIdc =
		" --set ScanMatcher:class=featloc::CfIdcMatcher --set ScanMatcher.CfIdcMatcher:fallback_class=";
	const CommandResult r = featlocRun(shellQuote(kConfig) + " --out " +
		shellQuote(dir.file("out")) + cfIdc);
	ASSERT_EQ(r.exitCode, 0) << r.output;
	const auto s = readJson(dir.file("out/summary.json"));
	const size_t counted = s["counts"]["guess_gate_overruled"];
	size_t rows = 0;
	double firstOverruled = -1;
	for (const auto& row : featloc::MatchTableFile::read(dir.file("out/matches.txt")))
	{
		if (row.status != "overruled") continue;
		rows++;
		if (firstOverruled < 0) firstOverruled = row.t;
		EXPECT_NE(row.reason.find("guess_gate_chi2"), std::string::npos) << row.reason;
		EXPECT_NE(row.reason.find("the scan's objects favour it over the guess by z ="), std::string::npos)
			<< row.reason;
	}
	EXPECT_GT(counted, 0u);
	EXPECT_EQ(rows, counted);

	TempDir off;
	const CommandResult o = featlocRun(shellQuote(kConfig) + " --out " +
		shellQuote(off.file("out")) + cfIdc + " --set ScanMatcher.CfIdcMatcher:coarse_overrule_guess_z=0");
	ASSERT_EQ(o.exitCode, 0) << o.output;
	const auto so = readJson(off.file("out/summary.json"));
	EXPECT_EQ(so["counts"]["guess_gate_overruled"], 0);
	// The first overruled match is the guess gate's failure there. (Later
	// ones need not be: an overruled match keeps its keyframe, a failed one
	// starts a new one, and the runs part.)
	bool gateThere = false;
	for (const auto& row : featloc::MatchTableFile::read(off.file("out/matches.txt")))
		if (std::abs(row.t - firstOverruled) < 1e-6) gateThere = row.status == "gate";
	EXPECT_TRUE(gateThere) << std::fixed << firstOverruled;
	EXPECT_GE(so["counts"]["match_failures_by_kind"]["guess_gate"].get<size_t>(), 1u);
}

// With the world the log was simulated in, featloc-bench puts each
// matcher's mean error beside the pairs' Cramer-Rao bound; no matcher beats
// it. Another world, or no ground truth, is refused before any matching.
TEST(FeatlocBench, ErrorsBesideTheCramerRaoBoundOfTheSimulatedWorld)
{
	TempDir dir;
	const std::string sim = std::string(FEATLOC_SOURCE_DIR) + "/rawlogs/sim/";
	const std::string worlds = std::string(FEATLOC_SOURCE_DIR) + "/worlds/";
	const std::string common = shellQuote(FEATLOC_BENCH_EXE) + " " + shellQuote(kConfig) + " " +
		shellQuote(sim + "office.rawlog") + " --max-pairs 60 -q";
	const CommandResult r = runCommand(common + " -g " + shellQuote(sim + "office.gt.txt") +
		" --world " + shellQuote(worlds + "office.ini") + " -j " + shellQuote(dir.file("b.json")) +
		" --pair-bounds " + shellQuote(dir.file("bounds.tsv")) +
		" -m featloc::PcmFeatureMatcher,featloc::IcpMatcher");
	ASSERT_EQ(r.exitCode, 0) << r.output;
	EXPECT_NE(r.output.find("| office.rawlog | featloc::PcmFeatureMatcher | 60 | "), std::string::npos)
		<< r.output;
	const auto j = readJson(dir.file("b.json"));
	for (const auto& m : j["results"])
	{
		const auto& c = m["cramer_rao"];
		ASSERT_EQ(c["pairs"], 60) << m["matcher"];
		// 361 beams, 1 cm noise, both scans noisy: about 1.3 mm per pair.
		EXPECT_GT(c["bound_mean_trans_m"].get<double>(), 0.0008);
		EXPECT_LT(c["bound_mean_trans_m"].get<double>(), 0.002);
		EXPECT_NEAR(c["mean_trans_err_m"].get<double>(), m["mean_trans_err_m"].get<double>(), 1e-12);
		EXPECT_GT(c["trans_ratio"].get<double>(), 1.0) << m["matcher"];
		EXPECT_GT(c["yaw_ratio"].get<double>(), 1.0) << m["matcher"];
	}
	// --pair-bounds: each pair's bound, whose mean is the table's, beside
	// its true motion (a robot driving forward: scan k - 1 to scan k).
	std::istringstream rows(readText(dir.file("bounds.tsv")));
	std::string line;
	size_t n = 0;
	double sumMeanT = 0;
	while (std::getline(rows, line))
	{
		if (line.rfind("#", 0) == 0) continue;
		std::vector<std::string> c;
		std::istringstream fields(line);
		for (std::string f; std::getline(fields, f, '\t');) c.push_back(f);
		ASSERT_EQ(c.size(), 15u) << line;
		EXPECT_EQ(c[0], "office.rawlog");
		EXPECT_EQ(std::stoul(c[1]), n);
		EXPECT_EQ(std::stoul(c[3]), std::stoul(c[2]) + 1) << line;
		EXPECT_LT(std::abs(std::stod(c[4])), 0.5) << "5 Hz: a step under 0.5 m";
		const double xx = std::stod(c[7]), yy = std::stod(c[10]), ww = std::stod(c[12]);
		EXPECT_GT(xx, 0) << line;
		EXPECT_GT(yy, 0) << line;
		EXPECT_GT(ww, 0) << line;
		EXPECT_LT(std::sqrt(xx + yy), 0.005) << line;
		EXPECT_LE(std::abs(std::stod(c[8])), std::sqrt(xx * yy) * (1 + 1e-9)) << line;
		sumMeanT += std::stod(c[13]);
		n++;
	}
	EXPECT_EQ(n, 60u);
	EXPECT_NEAR(sumMeanT / 60, j["results"][0]["cramer_rao"]["bound_mean_trans_m"].get<double>(), 1e-9);
	const CommandResult boundsWithoutWorld = runCommand(common + " -g " +
		shellQuote(sim + "office.gt.txt") + " --pair-bounds " + shellQuote(dir.file("x.tsv")));
	EXPECT_EQ(boundsWithoutWorld.exitCode, 2);
	EXPECT_NE(boundsWithoutWorld.output.find("--pair-bounds needs --world FILE"), std::string::npos)
		<< boundsWithoutWorld.output;

	const CommandResult other = runCommand(common + " -g " + shellQuote(sim + "office.gt.txt") +
		" --world " + shellQuote(worlds + "lab.ini"));
	EXPECT_NE(other.exitCode, 0);
	EXPECT_NE(other.output.find("lab.ini': scan 0 does not fit it at its ground-truth pose"),
		std::string::npos)
		<< other.output;
	const CommandResult noTruth = runCommand(common + " --reference-matcher featloc::IcpMatcher" +
		" --world " + shellQuote(worlds + "office.ini"));
	EXPECT_EQ(noTruth.exitCode, 2);
	EXPECT_NE(noTruth.output.find("--world needs the scans' ground truth"), std::string::npos)
		<< noTruth.output;
}

// A log of featloc-sim --frozen (nothing moving) fits its world file only
// with the world frozen the same way: --frozen. Without it the people of
// the world file are where the log has none, and the error says which
// option is missing.
TEST(FeatlocBench, AFrozenLogIsBoundByItsFrozenWorld)
{
	TempDir dir;
	const std::string world = std::string(FEATLOC_SOURCE_DIR) + "/worlds/corridor-people.ini";
	const CommandResult sim = runCommand(shellQuote(FEATLOC_SIM_EXE) + " " + shellQuote(world) +
		" --frozen -q --set Simulation:duration=4 --out " + shellQuote(dir.file("frozen")));
	ASSERT_EQ(sim.exitCode, 0) << sim.output;
	const std::string common = shellQuote(FEATLOC_BENCH_EXE) + " " + shellQuote(kConfig) + " " +
		shellQuote(dir.file("frozen.rawlog")) + " -g " + shellQuote(dir.file("frozen.gt.txt")) +
		" -q -m featloc::CfIdcMatcher --world " + shellQuote(world);
	const CommandResult moving = runCommand(common);
	EXPECT_EQ(moving.exitCode, 1) << moving.output;
	EXPECT_NE(moving.output.find("does not fit it at its ground-truth pose"), std::string::npos)
		<< moving.output;
	EXPECT_NE(moving.output.find("needs --frozen here too"), std::string::npos) << moving.output;

	const CommandResult frozen = runCommand(common + " --frozen -j " + shellQuote(dir.file("b.json")));
	ASSERT_EQ(frozen.exitCode, 0) << frozen.output;
	const auto j = readJson(dir.file("b.json"));
	EXPECT_GT(j["results"][0]["cramer_rao"]["pairs"].get<int>(), 10);
	EXPECT_EQ(j["results"][0]["points_kept"]["moved_seen"], 0) << "nothing moves";

	const CommandResult noWorld = runCommand(shellQuote(FEATLOC_BENCH_EXE) + " " +
		shellQuote(kConfig) + " " + shellQuote(dir.file("frozen.rawlog")) + " -g " +
		shellQuote(dir.file("frozen.gt.txt")) + " -q --frozen");
	EXPECT_EQ(noWorld.exitCode, 2) << noWorld.output;
	EXPECT_NE(noWorld.output.find("--frozen needs --world FILE"), std::string::npos)
		<< noWorld.output;
}

// With the world, featloc-bench also counts the current points on things
// that moved since the reference scan (people here) that CF-IDC kept for
// IDC: its segment gate drops most of them and keeps nearly all the rest;
// matchers that report no parts (ICP) are said to.
TEST(FeatlocBench, PointsOnThingsThatMovedAreCountedWithTheWorld)
{
	TempDir dir;
	const std::string sim = std::string(FEATLOC_SOURCE_DIR) + "/rawlogs/sim/";
	const CommandResult r = runCommand(shellQuote(FEATLOC_BENCH_EXE) + " " + shellQuote(kConfig) +
		" " + shellQuote(sim + "corridor-people.rawlog") + " -g " +
		shellQuote(sim + "corridor-people.gt.txt") + " --world " +
		shellQuote(std::string(FEATLOC_SOURCE_DIR) + "/worlds/corridor-people.ini") +
		" --max-pairs 80 -q -j " + shellQuote(dir.file("b.json")) +
		" -m featloc::CfIdcMatcher,featloc::IcpMatcher");
	ASSERT_EQ(r.exitCode, 0) << r.output;
	EXPECT_NE(r.output.find("| corridor-people.rawlog | featloc::IcpMatcher | (no parts reported) |"),
		std::string::npos)
		<< r.output;
	const auto j = readJson(dir.file("b.json"));
	const auto& k = j["results"][0]["points_kept"];
	const double moved = k["moved_seen"].get<double>(), still = k["still_seen"].get<double>();
	ASSERT_GT(moved, 50) << k;
	EXPECT_LT(k["moved_kept"].get<double>() / moved, 0.5) << k;
	EXPECT_GT(k["still_kept"].get<double>() / still, 0.9) << k;
	EXPECT_FALSE(j["results"][1].contains("points_kept"));
}

// Every pair counts: a failed pair with its guess's error, so a matcher
// that fails everything scores exactly the guesses' errors; a matcher that
// succeeds wrongly is a silent gross error. The basin curve is drawn.
TEST(FeatlocBench, EveryPairCountsAndTheBasinCurveIsDrawn)
{
	TempDir dir;
	const std::string sim = std::string(FEATLOC_SOURCE_DIR) + "/rawlogs/sim/";
	const std::string common = shellQuote(FEATLOC_BENCH_EXE) + " " + shellQuote(kConfig) + " " +
		shellQuote(sim + "office.rawlog") + " -g " + shellQuote(sim + "office.gt.txt") +
		" --max-pairs 60 -q --perturb-xy 0.3 --perturb-yaw-deg 10";
	const CommandResult r = runCommand(common + " -j " + shellQuote(dir.file("b.json")) +
		" --basin " + shellQuote(dir.file("basin.png")) + " --basin-levels 0.1/2,0.5/20" +
		" -m 'never=featloc::IcpMatcher{coarse_search=true;coarse_min_score=1},"
		"one=featloc::IcpMatcher{maxIterations=1;minGoodness=0},"
		"coarse=featloc::IdcMatcher{coarse_search=true}'");
	ASSERT_EQ(r.exitCode, 0) << r.output;
	const auto j = readJson(dir.file("b.json"));
	ASSERT_EQ(j["results"].size(), 3u);
	const auto& never = j["results"][0];
	EXPECT_EQ(never["failures"], 60);
	EXPECT_EQ(never["failures_by_kind"]["no_overlap"], 60);
	EXPECT_EQ(never["silent_gross_errors"], 0);
	EXPECT_EQ(never["success_rate"], 0.0);
	// Uniform +-0.3 m per axis: the guesses' mean |t| error is about 0.23 m.
	EXPECT_NEAR(never["mean_trans_err_m"].get<double>(), 0.23, 0.05);
	// One ICP iteration from +-0.3 m / +-10 deg leaves many pairs far off,
	// and nothing flags them.
	EXPECT_GT(j["results"][1]["silent_gross_errors"].get<int>(), 10);
	EXPECT_GT(j["results"][2]["success_rate"].get<double>(), 0.9);
	// The basin: two levels x three matchers, and the picture.
	ASSERT_EQ(j["basin"].size(), 6u);
	EXPECT_NEAR(j["basin"][5]["initial_error"]["yaw_deg"].get<double>(), 20, 1e-9);
	EXPECT_GT(std::filesystem::file_size(dir.file("basin.png")), 5000u);
	EXPECT_NE(r.output.find("| office.rawlog | coarse | +-0.50 m / +-20.0 deg |"), std::string::npos)
		<< r.output;
	const CommandResult bad = runCommand(common + " --basin x.png --basin-levels 0.1-2");
	EXPECT_EQ(bad.exitCode, 2);
	EXPECT_NE(bad.output.find("--basin-levels: '0.1-2'"), std::string::npos) << bad.output;
}

// --pairs: one row per matcher and pair, from which the tables' figures
// come back (the mean |t| error over every pair, failures at the guess's
// error; the NEES over the successes), and a failure carries the guess's
// covariance and the matcher's reason.
TEST(FeatlocBench, EveryPairsOutcomeIsWrittenAndGivesTheTablesFigures)
{
	TempDir dir;
	const std::string sim = std::string(FEATLOC_SOURCE_DIR) + "/rawlogs/sim/";
	const CommandResult r = runCommand(shellQuote(FEATLOC_BENCH_EXE) + " " + shellQuote(kConfig) +
		" " + shellQuote(sim + "office.rawlog") + " -g " + shellQuote(sim + "office.gt.txt") +
		" --max-pairs 40 -q --perturb-xy 0.3 --perturb-yaw-deg 10 --name office" +
		" -j " + shellQuote(dir.file("b.json")) + " --pairs " + shellQuote(dir.file("p.tsv")) +
		" -m 'never=featloc::IcpMatcher{coarse_search=true;coarse_min_score=1},idc=featloc::IdcMatcher'");
	ASSERT_EQ(r.exitCode, 0) << r.output;
	const auto j = readJson(dir.file("b.json"));
	std::istringstream rows(readText(dir.file("p.tsv")));
	std::string line;
	std::map<std::string, std::vector<std::vector<std::string>>> byMatcher;
	size_t header = 0;
	while (std::getline(rows, line))
	{
		if (line.rfind("#", 0) == 0)
		{
			header++;
			continue;
		}
		std::vector<std::string> c;
		size_t from = 0;
		for (size_t tab; (tab = line.find('\t', from)) != std::string::npos; from = tab + 1)
			c.push_back(line.substr(from, tab - from));
		c.push_back(line.substr(from));
		ASSERT_EQ(c.size(), 14u) << line;
		EXPECT_EQ(c[13].empty(), c[3] == "used") << line;
		EXPECT_EQ(c[0], "office");
		byMatcher[c[1]].push_back(c);
	}
	EXPECT_EQ(header, 1u);
	ASSERT_EQ(byMatcher["never"].size(), 40u);
	ASSERT_EQ(byMatcher["idc"].size(), 40u);
	for (size_t m = 0; m < 2; m++)
	{
		const auto& res = j["results"][m];
		const auto& table = byMatcher[res["matcher"].get<std::string>()];
		double sumT = 0, sumNees = 0;
		size_t successes = 0, gross = 0;
		for (size_t k = 0; k < table.size(); k++)
		{
			const auto& c = table[k];
			EXPECT_EQ(std::stoul(c[2]), k);
			const Eigen::Vector3d e(std::stod(c[4]), std::stod(c[5]), std::stod(c[6]));
			Eigen::Matrix3d P;
			P << std::stod(c[7]), std::stod(c[8]), std::stod(c[9]), std::stod(c[8]), std::stod(c[10]),
				std::stod(c[11]), std::stod(c[9]), std::stod(c[11]), std::stod(c[12]);
			sumT += std::hypot(e[0], e[1]);
			// Gross (> 10 cm or > 2 deg) in what is used, whatever the status.
			if (std::hypot(e[0], e[1]) > 0.1 || std::abs(e[2]) > mrpt::DEG2RAD(2.0)) gross++;
			if (c[3] == "failed")
			{
				// The guess's: uniform +-0.3 m / +-10 deg, sigma a / sqrt(3).
				EXPECT_NEAR(P(0, 0), 0.09 / 3, 1e-9);
				EXPECT_NEAR(P(2, 2), std::pow(mrpt::DEG2RAD(10.0), 2) / 3, 1e-9);
				if (res["matcher"] == "never")
				{
					EXPECT_NE(c[13].find("coarse search"), std::string::npos) << c[13];
				}
				continue;
			}
			sumNees += e.dot(P.ldlt().solve(e));
			successes++;
		}
		EXPECT_NEAR(sumT / 40, res["mean_trans_err_m"].get<double>(), 1e-6) << res["matcher"];
		EXPECT_EQ(res["gross_used"].get<size_t>(), gross) << res["matcher"];
		// The table's flagged cell: failed matches (the guess used) plus
		// flagged matches used, as the rows' statuses count them.
		size_t failed = 0, flaggedUsed = 0;
		for (const auto& c : table)
		{
			if (c[3] == "failed") failed++;
			else if (c[3] != "used") flaggedUsed++;
		}
		EXPECT_EQ(res["failures"].get<size_t>(), failed) << res["matcher"];
		EXPECT_EQ(res["ambiguous_used"].get<size_t>(), flaggedUsed) << res["matcher"];
		char cell[96];
		std::snprintf(cell, sizeof(cell), "| office | %s | 40 | %.1f%% = %.1f + %.1f |",
			res["matcher"].get<std::string>().c_str(), 2.5 * static_cast<double>(failed + flaggedUsed),
			2.5 * static_cast<double>(failed), 2.5 * static_cast<double>(flaggedUsed));
		EXPECT_NE(r.output.find(cell), std::string::npos) << cell << "\n" << r.output;
		EXPECT_GE(gross, res["silent_gross_errors"].get<size_t>()) << res["matcher"];
		if (res["matcher"] == "never")
		{
			EXPECT_EQ(successes, 0u);
			// Every failure hands on its guess, nearly always that far off.
			EXPECT_GT(gross, 34u);
		}
		else
		{
			ASSERT_GT(successes, 30u);
			EXPECT_NEAR(sumNees / static_cast<double>(successes), res["nees_mean"].get<double>(),
				1e-3 * res["nees_mean"].get<double>());
		}
	}
	// The paired comparison (by default with the IcpMatcher, "never"):
	// the pairs only one of the two gets grossly wrong, and the mean
	// difference, as the rows give them.
	const auto isGross = [](const std::vector<std::string>& c)
	{
		return std::hypot(std::stod(c[4]), std::stod(c[5])) > 0.1 ||
			std::abs(std::stod(c[6])) > mrpt::DEG2RAD(2.0);
	};
	size_t onlyIdc = 0, onlyNever = 0;
	double diff = 0;
	for (size_t k = 0; k < 40; k++)
	{
		const auto &i = byMatcher["idc"][k], &n = byMatcher["never"][k];
		onlyIdc += isGross(i) && !isGross(n);
		onlyNever += isGross(n) && !isGross(i);
		diff += std::hypot(std::stod(i[4]), std::stod(i[5])) - std::hypot(std::stod(n[4]), std::stod(n[5]));
	}
	EXPECT_FALSE(j["results"][0].contains("paired"));
	const auto& paired = j["results"][1]["paired"];
	EXPECT_EQ(paired["with"], "never");
	EXPECT_EQ(paired["gross_only_this"].get<size_t>(), onlyIdc);
	EXPECT_EQ(paired["gross_only_other"].get<size_t>(), onlyNever);
	EXPECT_GT(onlyNever, 30u);
	EXPECT_LT(paired["mcnemar_p"].get<double>(), 1e-6);
	EXPECT_NEAR(paired["mean_trans_err_diff_m"].get<double>(), diff / 40, 1e-9);
	EXPECT_LT(paired["ci95_m"][0].get<double>(), diff / 40);
	EXPECT_GT(paired["ci95_m"][1].get<double>(), diff / 40);
	EXPECT_LT(paired["ci95_m"][1].get<double>(), 0.0);  // IDC is clearly better
	EXPECT_NE(r.output.find("| office | idc | never | "), std::string::npos) << r.output;
}

// --paired-with names a matcher of -m, or "none"; a label that is not
// there is a usage error that lists the labels.
TEST(FeatlocBench, PairedWithNamesAMatcherOrNone)
{
	const std::string sim = std::string(FEATLOC_SOURCE_DIR) + "/rawlogs/sim/";
	const std::string common = shellQuote(FEATLOC_BENCH_EXE) + " " + shellQuote(kConfig) + " " +
		shellQuote(sim + "office.rawlog") + " -g " + shellQuote(sim + "office.gt.txt") +
		" --max-pairs 5 -q --name office -m 'a=featloc::IdcMatcher,b=featloc::PcmFeatureMatcher'";
	const CommandResult bad = runCommand(common + " --paired-with c");
	EXPECT_EQ(bad.exitCode, 2) << bad.output;
	EXPECT_NE(bad.output.find("--paired-with 'c' is not a matcher of -m (a, b)"), std::string::npos)
		<< bad.output;
	// No IcpMatcher among them: no comparison unless asked for.
	const CommandResult none = runCommand(common);
	ASSERT_EQ(none.exitCode, 0) << none.output;
	EXPECT_EQ(none.output.find("paired with"), std::string::npos) << none.output;
	const CommandResult withA = runCommand(common + " --paired-with a");
	ASSERT_EQ(withA.exitCode, 0) << withA.output;
	EXPECT_NE(withA.output.find("| office | b | a | "), std::string::npos) << withA.output;
	EXPECT_EQ(withA.output.find("| office | a | a | "), std::string::npos) << withA.output;
}

// scripts/reference-error-share.py on outcomes whose errors are known: four
// matchers, each with its own error, plus one reference error per pair that
// all share. A, B and C report their own error's covariance; D reports half
// its standard deviation (over-confident). Against the reference every NEES
// is far above 3; the three-cornered hat finds each one's own spread (A's
// as reported, D's twice what it reports) and the shared one, and the
// difference NEES is 3 between consistent matchers and above it with D.
TEST(ReferenceErrorShare, SplitsKnownOwnAndSharedErrors)
{
	TempDir dir;
	mrpt::random::CRandomGenerator rng(5);
	const double reported[3] = {0.005, 0.005, mrpt::DEG2RAD(0.05)};
	const double shared[3] = {0.02, 0.02, mrpt::DEG2RAD(0.3)};
	{
		std::ofstream f(dir.file("p.tsv"));
		f << "# data\tmatcher\tpair\tstatus\terr_x_m\terr_y_m\terr_yaw_rad\tcov_xx\tcov_xy\tcov_xyaw\tcov_yy\tcov_yyaw\tcov_yawyaw\treason\n";
		std::vector<Eigen::Vector3d> ref(4000);
		for (auto& e : ref)
			for (int i = 0; i < 3; i++) e[i] = shared[i] * rng.drawGaussian1D_normalized();
		for (const std::string m : {"A", "B", "C", "D"})
			for (size_t k = 0; k < ref.size(); k++)
			{
				const double own = m == "D" ? 2.0 : 1.0;
				Eigen::Vector3d e;
				for (int i = 0; i < 3; i++)
					e[i] = own * reported[i] * rng.drawGaussian1D_normalized() - ref[k][i];
				f << "log\t" << m << "\t" << k << "\tused\t" << e[0] << "\t" << e[1] << "\t" << e[2]
				  << "\t" << reported[0] * reported[0] << "\t0\t0\t" << reported[1] * reported[1]
				  << "\t0\t" << reported[2] * reported[2] << "\t\n";
			}
	}
	const CommandResult r = runCommand("python3 " +
		shellQuote(std::string(FEATLOC_SOURCE_DIR) + "/scripts/reference-error-share.py") + " " +
		shellQuote(dir.file("p.tsv")));
	ASSERT_EQ(r.exitCode, 0) << r.output;
	std::map<std::string, std::vector<std::string>> hat, difference;
	std::istringstream rows(r.output);
	for (std::string line; std::getline(rows, line);)
	{
		if (line.rfind("| log |", 0) != 0) continue;
		std::vector<std::string> c;
		std::istringstream cells(line);
		for (std::string cell; std::getline(cells, cell, '|');)
			c.push_back(cell.size() >= 2 ? cell.substr(1, cell.size() - 2) : "");
		if (c.size() == 10) hat[c[2]] = c;  // | log | A | with | pairs | NEES | own | reported | ratio | shared |
		if (c.size() == 6) difference[c[2] + "-" + c[3]] = c;  // | log | A | B | pairs | NEES |
	}
	ASSERT_EQ(hat.size(), 4u) << r.output;
	ASSERT_EQ(difference.size(), 6u) << r.output;
	auto numbers = [](const std::string& cell) {
		std::vector<double> v;
		std::istringstream in(cell);
		for (std::string x; std::getline(in, x, ',');) v.push_back(std::stod(x));
		return v;
	};
	// Against the reference: (reported^2 + shared^2) / reported^2 per axis,
	// 17 + 17 + 37 = 71 for A.
	EXPECT_GT(std::stod(hat["A"][5]), 50) << r.output;
	const auto ownA = numbers(hat["A"][6]);
	ASSERT_EQ(ownA.size(), 3u);
	EXPECT_NEAR(ownA[0], 5.0, 0.6);	 // [mm]
	EXPECT_NEAR(ownA[2], 0.05, 0.006);	// [deg]
	for (double ratio : numbers(hat["A"][8])) EXPECT_NEAR(ratio, 1.0, 0.15) << r.output;
	for (double ratio : numbers(hat["D"][8])) EXPECT_NEAR(ratio, 2.0, 0.2) << r.output;
	const auto sharedA = numbers(hat["A"][9]);
	EXPECT_NEAR(sharedA[0], 20.0, 1.5);	 // [mm]
	EXPECT_NEAR(sharedA[2], 0.3, 0.03);	 // [deg]
	EXPECT_NEAR(std::stod(difference["A-B"][5]), 3.0, 0.25) << r.output;
	// (1 + 4) / (1 + 1) per axis with D.
	EXPECT_NEAR(std::stod(difference["A-D"][5]), 7.5, 0.8) << r.output;
}

// scripts/pair-bound-ratios.py on outcomes whose errors are known against a
// correlated bound B: "efficient" draws its errors from B and reports B,
// "twice" draws them from 4 B and reports B, "claims" draws from B and
// reports B / 4. Failed, gross and unbounded pairs are left out.
TEST(PairBoundRatios, FindsHowFarFromTheBoundAndWhoClaimsToBeatIt)
{
	TempDir dir;
	mrpt::random::CRandomGenerator rng(7);
	Eigen::Matrix3d B;
	B << 4e-6, 1.5e-6, 2e-7, 1.5e-6, 2e-6, -1e-7, 2e-7, -1e-7, 1e-7;
	const Eigen::Matrix3d L = B.llt().matrixL();
	const size_t n = 3000;
	{
		std::ofstream p(dir.file("p.tsv")), b(dir.file("b.tsv"));
		p << "# data\tmatcher\tpair\tstatus\terr_x_m\terr_y_m\terr_yaw_rad\tcov_xx\tcov_xy\tcov_xyaw\tcov_yy\tcov_yyaw\tcov_yawyaw\treason\n";
		b << "# data\tpair\treference_scan\tcurrent_scan\ttrue_x_m\ttrue_y_m\ttrue_yaw_rad\tcrb_xx\tcrb_xy\tcrb_xyaw\tcrb_yy\tcrb_yyaw\tcrb_yawyaw\tcrb_mean_t_m\tcrb_mean_w_rad\n";
		p.precision(12);
		b.precision(12);
		auto row = [](std::ostream& f, const Eigen::Matrix3d& m) {
			f << m(0, 0) << "\t" << m(0, 1) << "\t" << m(0, 2) << "\t" << m(1, 1) << "\t" << m(1, 2)
			  << "\t" << m(2, 2);
		};
		for (size_t k = 0; k < n + 1; k++)
		{
			b << "log\t" << k << "\t" << k << "\t" << k + 1 << "\t0.1\t0\t0\t";
			if (k == n)
				b << "nan\tnan\tnan\tnan\tnan\tnan\tnan\tnan\n";  // no bound: left out
			else
			{
				row(b, B);
				b << "\t0.002\t0.0003\n";
			}
		}
		for (const std::string m : {"efficient", "twice", "claims"})
			for (size_t k = 0; k < n + 1; k++)
			{
				Eigen::Vector3d z;
				for (int i = 0; i < 3; i++) z[i] = rng.drawGaussian1D_normalized();
				Eigen::Vector3d e = L * z * (m == "twice" ? 2.0 : 1.0);
				std::string status = "used";
				if (k == 5) status = "failed";
				if (k == 6) e[0] = 0.2;  // gross: left out
				p << "log\t" << m << "\t" << k << "\t" << status << "\t" << e[0] << "\t" << e[1]
				  << "\t" << e[2] << "\t";
				row(p, m == "claims" ? Eigen::Matrix3d(B / 4) : B);
				p << "\t" << (status == "used" ? "" : "no convergence") << "\n";
			}
		// A second data set in the same files gets its own rows.
		for (size_t k = 0; k < 50; k++)
		{
			b << "second\t" << k << "\t" << k << "\t" << k + 1 << "\t0.1\t0\t0\t";
			row(b, B);
			b << "\t0.002\t0.0003\n";
			p << "second\tefficient\t" << k << "\tused\t0.001\t0\t0\t";
			row(p, B);
			p << "\t\n";
		}
	}
	const CommandResult r = runCommand("python3 " +
		shellQuote(std::string(FEATLOC_SOURCE_DIR) + "/scripts/pair-bound-ratios.py") + " " +
		shellQuote(dir.file("p.tsv")) + " " + shellQuote(dir.file("b.tsv")));
	ASSERT_EQ(r.exitCode, 0) << r.output;
	std::map<std::string, std::vector<std::string>> rows;
	std::istringstream out(r.output);
	for (std::string line; std::getline(out, line);)
	{
		if (line.rfind("| log |", 0) != 0) continue;
		std::vector<std::string> c;
		std::istringstream cells(line);
		for (std::string cell; std::getline(cells, cell, '|');)
			c.push_back(cell.size() >= 2 ? cell.substr(1, cell.size() - 2) : "");
		ASSERT_EQ(c.size(), 10u) << line;  // | log | m | n | NEES | axes | eff | rms | claimed | under |
		rows[c[2]] = c;
	}
	ASSERT_EQ(rows.size(), 3u) << r.output;
	EXPECT_NE(r.output.find("| second | efficient | 50 | "), std::string::npos) << r.output;
	auto first = [](const std::string& cell) { return std::stod(cell.substr(0, cell.find(' '))); };
	auto numbers = [](const std::string& cell) {
		std::vector<double> v;
		std::istringstream in(cell);
		for (std::string x; std::getline(in, x, ',');) v.push_back(std::stod(x));
		return v;
	};
	for (const auto& [m, c] : rows) EXPECT_EQ(c[3], std::to_string(n - 2)) << m;
	EXPECT_NEAR(first(rows["efficient"][4]), 3.0, 0.2);
	EXPECT_NEAR(first(rows["efficient"][6]), 3.0, 0.2);
	EXPECT_NEAR(first(rows["twice"][4]), 12.0, 0.8);
	EXPECT_NEAR(first(rows["twice"][6]), 12.0, 0.8);
	EXPECT_NEAR(first(rows["claims"][4]), 12.0, 0.8);
	EXPECT_NEAR(first(rows["claims"][6]), 3.0, 0.2);
	// The NEES split along the claimed covariance's axes: 1 each where it
	// is consistent, 4 each where it claims half the spread.
	for (double v : numbers(rows["efficient"][5])) EXPECT_NEAR(v, 1.0, 0.1);
	for (double v : numbers(rows["claims"][5])) EXPECT_NEAR(v, 4.0, 0.4);
	for (double v : numbers(rows["efficient"][7])) EXPECT_NEAR(v, 1.0, 0.06);
	for (double v : numbers(rows["twice"][7])) EXPECT_NEAR(v, 2.0, 0.12);
	for (double v : numbers(rows["twice"][8])) EXPECT_NEAR(v, 1.0, 1e-6);
	for (double v : numbers(rows["claims"][8])) EXPECT_NEAR(v, 0.5, 1e-6);
	EXPECT_EQ(rows["efficient"][9], "0.0%");
	EXPECT_EQ(rows["twice"][9], "0.0%");
	EXPECT_EQ(rows["claims"][9], "100.0%");
}

// IDC's point-to-line phase can cycle for ever: points change lines as the
// estimate moves a few millimetres, and the same poses come back. On the
// Radish belgioioso log, pair 103 under Borges & Aldon's protocol (seed 1)
// cycles through 22 poses 7 mm and 0.2 deg apart; with only 16 iterations
// remembered it ran to max_iterations and failed ("no convergence"), 7 mm
// from the reference pose.
TEST(FeatlocBench, IdcCatchesALongCycleOfPairingsOnARealLog)
{
	const std::string log =
		std::string(FEATLOC_SOURCE_DIR) + "/../shared/data/laser2d/belgioioso-corrected.log.gz";
	if (!std::filesystem::exists(log)) GTEST_SKIP() << "no " << log;
	TempDir dir;
	const CommandResult r = runCommand(shellQuote(FEATLOC_BENCH_EXE) + " " + shellQuote(kConfig) +
		" " + shellQuote(log) + " --max-pairs 104 --seed 1 -q --perturb-xy 0.3 --perturb-yaw-deg 10" +
		" -m featloc::IdcMatcher -j " + shellQuote(dir.file("b.json")));
	ASSERT_EQ(r.exitCode, 0) << r.output;
	const auto m = readJson(dir.file("b.json"))["results"][0];
	EXPECT_EQ(m["pairs"], 104);
	EXPECT_EQ(m["failures"], 0) << m["failure_examples"];
	EXPECT_LT(m["mean_trans_err_m"].get<double>(), 0.04);
}

// fallback_class in a run: along a corridor whose only cross features are
// door jambs, PCM fails where they are far (too few points for a feature)
// and ICP makes those matches, and only those; summary.json counts them and
// matches.txt says whose they are.
TEST(FeatlocRun, TheFallbackMatcherMakesTheMatchesPcmCannot)
{
	registerClasses();
	TempDir dir;
	featloc::test::SyntheticRoom corridor = featloc::test::SyntheticRoom::corridor();
	for (double x : {-2.0, 0.7, 1.9, 3.2})
	{
		corridor.add(x, 1, x, 0.92);
		corridor.add(x, -1, x, -0.92);
	}
	TestRawlog log;
	log.scans = 12;
	log.path = [](double t) { return CPose2D(0.5 * t, 0.02 * t, 0.01 * t); };
	writeWithScansOf(log, corridor, dir.file("corridor.rawlog"));
	const std::string common = pcmChainEveryScanArgs(dir.file("corridor.rawlog"));
	const CommandResult alone = featlocRun(
		common + " --out " + shellQuote(dir.file("alone")) +
		" --set ScanMatcher.PcmFeatureMatcher:fallback_class=");
	ASSERT_EQ(alone.exitCode, 0) << alone.output;
	const auto a = readJson(dir.file("alone/summary.json"));
	const int pcmFailures = a["counts"]["match_failures"].get<int>();
	EXPECT_GE(pcmFailures, 3);
	EXPECT_EQ(a["counts"]["fallback_matcher_matches"], 0);

	// Failures only: with fallback_above_sigma_xy (PCM's default 0.01 m)
	// its weak matches go to the fallback too (11 of 11 here).
	const CommandResult r = featlocRun(common + " --out " + shellQuote(dir.file("out")) +
		" --set ScanMatcher.PcmFeatureMatcher:fallback_class=IcpMatcher"
		" --set ScanMatcher.PcmFeatureMatcher:fallback_above_sigma_xy=0");
	ASSERT_EQ(r.exitCode, 0) << r.output;
	const auto s = readJson(dir.file("out/summary.json"));
	EXPECT_EQ(s["counts"]["matches"], 11);
	EXPECT_EQ(s["counts"]["match_failures"], 0);
	EXPECT_EQ(s["counts"]["fallback_matcher_matches"], pcmFailures);
	EXPECT_EQ(s["counts"]["fallback_matcher_successes"], pcmFailures);
	const std::string matches = readText(dir.file("out/matches.txt"));
	EXPECT_NE(matches.find("made by the fallback matcher after featloc::PcmFeatureMatcher: "),
		std::string::npos)
		<< matches.substr(0, 2000);
}

// coarse_confirm_share in a run: in a room whose corners fix every
// direction, the points confirm PCM's iterations from the odometry guess
// and the coarse search is not run; summary.json and the console count
// those matches, and with the key at 0 the search runs for every match.
TEST(FeatlocRun, SummaryCountsTheMatchesMadeWithoutTheCoarseSearch)
{
	registerClasses();
	TempDir dir;
	const featloc::test::SyntheticRoom room = featloc::test::SyntheticRoom::office();
	TestRawlog log;
	log.scans = 12;
	log.path = [](double t) { return CPose2D(0.3 * t, 0.05 * t, 0.05 * t); };
	writeWithScansOf(log, room, dir.file("room.rawlog"));
	const std::string common = pcmChainEveryScanArgs(dir.file("room.rawlog"));
	const CommandResult r = featlocRun(common + " --out " + shellQuote(dir.file("out")));
	ASSERT_EQ(r.exitCode, 0) << r.output;
	const auto s = readJson(dir.file("out/summary.json"));
	EXPECT_EQ(s["counts"]["matches"], 11);
	EXPECT_EQ(s["counts"]["match_failures"], 0);
	EXPECT_EQ(s["counts"]["coarse_search_skipped"], 11);
	EXPECT_EQ(s["counts"]["coarse_confirmations_slid"], 0) << "the corners fix every direction";
	EXPECT_NE(r.output.find("11 without the coarse search: the points confirmed the iterations"),
		std::string::npos)
		<< r.output;

	const CommandResult always = featlocRun(common + " --out " + shellQuote(dir.file("always")) +
		" --set ScanMatcher.PcmFeatureMatcher:coarse_confirm_share=0");
	ASSERT_EQ(always.exitCode, 0) << always.output;
	const auto a = readJson(dir.file("always/summary.json"));
	EXPECT_EQ(a["counts"]["match_failures"], 0);
	EXPECT_EQ(a["counts"]["coarse_search_skipped"], 0);
	EXPECT_EQ(always.output.find("without the coarse search"), std::string::npos);
}

// The bundled log's readings sit on multiples of 0.16 m (MRPT's simulator):
// the run says so, and that the featloc matcher put them back on their
// surfaces; MRPT's ICP, as MRPT runs it, leaves them as they are.
TEST(FeatlocRun, SummaryTellsTheRangeLatticeAndWhatTheMatcherDidWithIt)
{
	TempDir dir;
	const std::string common = shellQuote(kConfig) + " --set Input:max_scans=60";
	const CommandResult r = featlocRun(common + " --out " + shellQuote(dir.file("idc")) +
		" --set ScanMatcher:class=featloc::IdcMatcher");
	ASSERT_EQ(r.exitCode, 0) << r.output;
	const auto s = readJson(dir.file("idc/summary.json"))["counts"];
	const int matches = s["matches"].get<int>();
	EXPECT_GE(matches, 50);
	EXPECT_EQ(s["range_lattice_matches"].get<int>(), matches);
	EXPECT_EQ(s["dequantized_matches"].get<int>(), matches);
	EXPECT_NEAR(s["range_lattice_step_m"].get<double>(), 0.16, 0.002);
	EXPECT_NE(r.output.find("with the current scan's ranges on a lattice of 0.160 m"), std::string::npos)
		<< r.output;

	const CommandResult icp = featlocRun(common + " --out " + shellQuote(dir.file("icp")));
	ASSERT_EQ(icp.exitCode, 0) << icp.output;
	const auto i = readJson(dir.file("icp/summary.json"))["counts"];
	EXPECT_EQ(i["range_lattice_matches"].get<int>(), 0);
	EXPECT_EQ(i["dequantized_matches"].get<int>(), 0);
	EXPECT_EQ(icp.output.find("on a lattice"), std::string::npos);
}
