// App-level tests of featloc-viewer: the real app in a real window under
// Xvfb, on the results of real runs of the bundled log; its --screenshot
// PNGs are checked for what must be drawn.
#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "featloc/eval/TrajectoryFile.h"
#include "support/CommandRunner.h"
#include "support/FreePort.h"
#include "support/LiveEmulator.h"
#include "support/TempDir.h"

using featloc::test::CommandResult;
using featloc::test::emulatorCommand;
using featloc::test::freePort;
using featloc::test::liveArgs;
using featloc::test::runCommand;
using featloc::test::shellQuote;
using featloc::test::TempDir;
namespace fs = std::filesystem;

namespace
{
const std::string kRun = FEATLOC_RUN_EXE;
const std::string kViewer = FEATLOC_VIEWER_EXE;
const std::string kSource = FEATLOC_SOURCE_DIR;
const std::string kConfig = kSource + "/config.ini";
const std::string kLive = FEATLOC_LIVE_EXE;

// MapCanvas's colours (RGB 30,80,220 / 20,170,60 / 230,30,30 / 0,190,190),
// told apart by their dominant hue: lines are antialiased, so their pixels
// are blends with the white background.
enum class Hue
{
	Blue,
	Green,
	Red,
	Cyan
};
const Hue kTrajectory = Hue::Blue, kGroundTruth = Hue::Green, kCurrentScan = Hue::Red,
		  kReferenceScan = Hue::Cyan;

std::string runInto(const std::string& dir, const std::string& estimator)
{
	const CommandResult r = runCommand(shellQuote(kRun) + " " + shellQuote(kConfig) + " --out " +
		shellQuote(dir) + " -q --set Pipeline:estimator=" + estimator + " 2>&1");
	EXPECT_EQ(r.exitCode, 0) << r.output;
	return dir;
}

CommandResult viewer(const std::string& args)
{
	// Run from the source folder, where config.ini's relative ground-truth
	// path points, as a user would.
	return runCommand("cd " + shellQuote(kSource) + " && xvfb-run -a -s '-screen 0 1600x1200x24' " +
		shellQuote(kViewer) + " " + args + " 2>&1");
}

cv::Mat screenshot(const std::string& results, const std::string& png, const std::string& extra)
{
	const CommandResult r =
		viewer(shellQuote(results) + " --screenshot " + shellQuote(png) + " " + extra);
	EXPECT_EQ(r.exitCode, 0) << r.output;
	cv::Mat bgr = cv::imread(png, cv::IMREAD_COLOR);
	EXPECT_FALSE(bgr.empty()) << png << " was not written: " << r.output;
	return bgr;
}

bool is(const cv::Vec3b& bgr, Hue hue)
{
	const int b = bgr[0], g = bgr[1], r = bgr[2];
	switch (hue)
	{
		case Hue::Blue: return b > g + 30 && b > r + 60;
		case Hue::Green: return g > r + 40 && g > b + 20;
		case Hue::Red: return r > g + 100 && r > b + 100;
		case Hue::Cyan: return g > r + 80 && b > r + 80 && std::abs(g - b) < 40;
	}
	return false;
}

// Rows above this are the timeline and the tabs (at --size 1200x850).
constexpr int kMapTop = 90;

std::vector<cv::Point> pixelsOf(const cv::Mat& img, Hue hue)
{
	std::vector<cv::Point> out;
	for (int y = 0; y < img.rows; y++)
		for (int x = 0; x < img.cols; x++)
			if (is(img.at<cv::Vec3b>(y, x), hue)) out.emplace_back(x, y);
	return out;
}

// The trajectory is drawn where it is: the blue pixels' bounding box has
// the world trajectory's aspect ratio (one scale on both axes), and the
// first pose, placed in that box with y up, lands on a blue pixel.
void expectTrajectoryDrawn(const cv::Mat& img, const std::string& posesCov)
{
	const auto traj = featloc::TrajectoryFile::read(posesCov).poses;
	double minX = 1e9, maxX = -1e9, minY = 1e9, maxY = -1e9;
	for (const auto& p : traj)
		minX = std::min(minX, p.pose.x), maxX = std::max(maxX, p.pose.x),
		minY = std::min(minY, p.pose.y), maxY = std::max(maxY, p.pose.y);
	// Below the timeline and the page tabs, whose GTK theme is blue too.
	std::vector<cv::Point> blue;
	for (const auto& p : pixelsOf(img, kTrajectory))
		if (p.y >= kMapTop) blue.push_back(p);
	ASSERT_GT(blue.size(), 300u) << "trajectory pixels";
	const cv::Rect box = cv::boundingRect(blue);
	EXPECT_NEAR(box.width / double(box.height), (maxX - minX) / (maxY - minY), 0.05)
		<< "world and screen aspect ratios differ";
	const double u = box.x + (traj[0].pose.x - minX) / (maxX - minX) * box.width;
	const double v = box.y + (maxY - traj[0].pose.y) / (maxY - minY) * box.height;
	const bool onIt = std::any_of(blue.begin(), blue.end(), [&](const cv::Point& p) {
		return std::hypot(p.x - u, p.y - v) <= 5;
	});
	EXPECT_TRUE(onIt) << "no trajectory pixel where the first pose is (" << u << ", " << v << ")";
}
}  // namespace

TEST(Viewer, OpensOdometryMatcherAndEkfResultsAndDrawsTheirMaps)
{
	TempDir tmp;
	for (const std::string estimator : {"odometry", "matcher", "ekf"})
	{
		SCOPED_TRACE(estimator);
		const std::string dir = runInto(tmp.file(estimator), estimator);
		const cv::Mat img =
			screenshot(dir, tmp.file(estimator + ".png"), "--step 252 --size 1200x850");
		ASSERT_FALSE(img.empty());
		expectTrajectoryDrawn(img, dir + "/poses_cov.txt");
		EXPECT_GT(pixelsOf(img, kGroundTruth).size(), 300u) << "ground truth pixels";
		EXPECT_GT(pixelsOf(img, kCurrentScan).size(), 50u) << "current scan pixels";
		if (estimator != "odometry")  // only matches have a reference scan
		{
			EXPECT_GT(pixelsOf(img, kReferenceScan).size(), 20u) << "reference scan pixels";
		}
	}
}

TEST(Viewer, MatchViewShowsWhyAMatchWasNotUsedAndReproducesIt)
{
	TempDir tmp;
	const std::string dir = runInto(tmp.file("ekf"), "ekf");
	const CommandResult r = viewer(
		shellQuote(dir) + " --view match --step 252 --screenshot " + shellQuote(tmp.file("m.png")));
	ASSERT_EQ(r.exitCode, 0) << r.output;
	// Step 252 is where the log's odometry was read off the scan's instant:
	// the EKF's gate refused ICP's match (doc/benchmarks.md, issue 17).
	EXPECT_NE(r.output.find("status: ok, NOT used"), std::string::npos) << r.output;
	EXPECT_NE(r.output.find("reason: the match disagrees with the prediction"), std::string::npos)
		<< r.output;
	// Run again on the same pair with the same guess, ICP finds the same
	// motion.
	const auto first = r.output.find("estimate: ");
	const auto second = r.output.find("estimate: ", first + 1);
	ASSERT_NE(second, std::string::npos) << r.output;
	EXPECT_EQ(r.output.substr(first, r.output.find('\n', first) - first),
		r.output.substr(second, r.output.find('\n', second) - second));
	EXPECT_NE(r.output.find("what it used: "), std::string::npos) << r.output;
	const cv::Mat img = cv::imread(tmp.file("m.png"));
	ASSERT_FALSE(img.empty());
	EXPECT_GT(pixelsOf(img, Hue::Red).size(), 200u) << "current scan in the match view";
}

TEST(Viewer, MatchViewShowsPcmFeaturesAndCfIdcSegments)
{
	TempDir tmp;
	for (const std::string cls : {"PcmFeatureMatcher", "CfIdcMatcher"})
	{
		SCOPED_TRACE(cls);
		const std::string dir = tmp.file(cls);
		// PCM without its fallback: step 100 is a corridor stretch where
		// its lines fail it, and the view shows its features anyway.
		const CommandResult run = runCommand(shellQuote(kRun) + " " + shellQuote(kConfig) +
			" --out " + shellQuote(dir) + " -q --set ScanMatcher:class=featloc::" + cls +
			" --set ScanMatcher.PcmFeatureMatcher:fallback_class= 2>&1");
		ASSERT_EQ(run.exitCode, 0) << run.output;
		const CommandResult r = viewer(shellQuote(dir) + " --view match --step 100 --screenshot " +
			shellQuote(tmp.file(cls + ".png")));
		ASSERT_EQ(r.exitCode, 0) << r.output;
		EXPECT_NE(r.output.find("lines, clusters or segments kept"), std::string::npos) << r.output;
		if (cls == "PcmFeatureMatcher")
		{
			EXPECT_NE(r.output.find("PCM feature pairs"), std::string::npos) << r.output;
		}
	}
	// With config.ini's fallback (IDC) a match PCM's lines fail is IDC's,
	// and the view says so, in the run's row and when run again: the first
	// such step of the run (matches.txt's data row k is step k).
	const std::string dir = tmp.file("pcm-fallback");
	const CommandResult run = runCommand(shellQuote(kRun) + " " + shellQuote(kConfig) + " --out " +
		shellQuote(dir) + " -q --set ScanMatcher:class=featloc::PcmFeatureMatcher 2>&1");
	ASSERT_EQ(run.exitCode, 0) << run.output;
	std::ifstream rows(dir + "/matches.txt");
	std::string row;
	size_t step = 0, k = 0;
	while (step == 0 && std::getline(rows, row))
	{
		if (row.empty() || row[0] == '#') continue;
		k++;
		if (row.find("made by the fallback matcher") != std::string::npos) step = k;
	}
	ASSERT_GT(step, 0u) << "no match made by the fallback";
	const CommandResult r = viewer(shellQuote(dir) + " --view match --step " +
		std::to_string(step) + " --screenshot " + shellQuote(tmp.file("pcm-fallback.png")));
	ASSERT_EQ(r.exitCode, 0) << r.output;
	EXPECT_NE(r.output.find("reason: made by the fallback matcher after featloc::PcmFeatureMatcher: "),
		std::string::npos)
		<< r.output;
	EXPECT_NE(r.output.find("featloc::PcmFeatureMatcher: success by its fallback featloc::IdcMatcher"),
		std::string::npos)
		<< r.output;
	EXPECT_EQ(r.output.find("PCM feature pairs"), std::string::npos) << r.output;
}

TEST(Viewer, PlotsShowErrorNeesAndMatchTime)
{
	TempDir tmp;
	const std::string dir = runInto(tmp.file("ekf"), "ekf");
	const cv::Mat img = screenshot(dir, tmp.file("p.png"), "--view plots --step 400");
	ASSERT_FALSE(img.empty());
	EXPECT_GT(pixelsOf(img, Hue::Blue).size(), 2000u) << "three series";
	size_t band = 0;  // the NEES band's light green (200, 235, 200)
	for (int y = 0; y < img.rows; y++)
		for (int x = 0; x < img.cols; x++)
		{
			const auto& p = img.at<cv::Vec3b>(y, x);
			band += p[2] == 200 && p[1] == 235 && p[0] == 200;
		}
	EXPECT_GT(band, 5000u) << "NEES 95% band";
}

TEST(Viewer, OpensARawlogByRunningItFirst)
{
	TempDir tmp;
	const CommandResult r = viewer(shellQuote(kSource + "/rawlogs/mrpt-simul/simul.rawlog") +
		" --screenshot " + shellQuote(tmp.file("r.png")));
	ASSERT_EQ(r.exitCode, 0) << r.output;
	EXPECT_NE(r.output.find("running featloc-run"), std::string::npos) << r.output;
	const cv::Mat img = cv::imread(tmp.file("r.png"));
	ASSERT_FALSE(img.empty());
	EXPECT_GT(pixelsOf(img, kTrajectory).size(), 300u);
}

TEST(Viewer, MissingOrDamagedFilesOpenWhatItCanAndSaySo)
{
	TempDir tmp;
	const std::string dir = runInto(tmp.file("ekf"), "ekf");
	fs::remove(dir + "/nees.txt");
	std::ofstream(dir + "/matches.txt", std::ios::app) << "1.0 garbage\n";
	const cv::Mat img = screenshot(dir, tmp.file("d.png"), "");
	ASSERT_FALSE(img.empty());
	EXPECT_GT(pixelsOf(img, kTrajectory).size(), 300u) << "the map still opens";
	const CommandResult r = viewer(shellQuote(dir) + " --screenshot " + shellQuote(tmp.file("e.png")));
	EXPECT_NE(r.output.find("nees.txt is missing"), std::string::npos) << r.output;
	EXPECT_NE(r.output.find("matches.txt could not be read"), std::string::npos) << r.output;
	EXPECT_NE(r.output.find("not a match-table row"), std::string::npos) << r.output;
}

TEST(Viewer, BadInputsAreClearErrorsNotCrashes)
{
	TempDir tmp;
	const std::string dir = runInto(tmp.file("odo"), "odometry");
	// No display.
	CommandResult r = runCommand("env -u DISPLAY -u WAYLAND_DISPLAY " + shellQuote(kViewer) + " " +
		shellQuote(dir) + " 2>&1");
	EXPECT_EQ(r.exitCode, 1) << r.output;
	EXPECT_NE(r.output.find("needs a display"), std::string::npos) << r.output;
	// A folder that is not a results folder, a missing input.
	r = viewer(shellQuote(tmp.path().string()) + " --screenshot /dev/null");
	EXPECT_EQ(r.exitCode, 1) << r.output;
	EXPECT_NE(r.output.find("has no poses_cov.txt"), std::string::npos) << r.output;
	r = viewer(shellQuote(tmp.file("nothing-here")));
	EXPECT_EQ(r.exitCode, 1) << r.output;
	EXPECT_NE(r.output.find("no such file or folder"), std::string::npos) << r.output;
	// Usage errors: exit 2.
	r = viewer(shellQuote(dir) + " --view sideways");
	EXPECT_EQ(r.exitCode, 2) << r.output;
	EXPECT_NE(r.output.find("--view must be map, match, plots or stereo"), std::string::npos) << r.output;
	r = viewer(shellQuote(dir) + " --step 100000 --screenshot /dev/null");
	EXPECT_EQ(r.exitCode, 2) << r.output;
}

TEST(Viewer, RematchRunsAnotherClassOrParametersOnTheSamePair)
{
	TempDir tmp;
	const std::string dir = runInto(tmp.file("m"), "matcher");
	const std::string base =
		shellQuote(dir) + " --view match --step 120 --screenshot " + shellQuote(tmp.file("r.png"));
	CommandResult r = viewer(base + " --rematch IdcMatcher --rematch-set 'max_iterations = 3'");
	ASSERT_EQ(r.exitCode, 0) << r.output;
	EXPECT_NE(r.output.find("re-matched: featloc::IdcMatcher: failed, 3 iterations"),
		std::string::npos) << r.output;
	EXPECT_NE(r.output.find("no convergence in 3 iterations"), std::string::npos) << r.output;
	r = viewer(base + " --rematch PcmFeatureMatcher");
	ASSERT_EQ(r.exitCode, 0) << r.output;
	EXPECT_NE(r.output.find("re-matched: featloc::PcmFeatureMatcher: success"), std::string::npos)
		<< r.output;
	// A key the class does not have is an error naming the section and key,
	// with featloc-run's "did you mean".
	r = viewer(base + " --rematch IdcMatcher --rematch-set maxIterations=5");
	EXPECT_NE(r.output.find("[ScanMatcher.IdcMatcher] maxIterations: unknown key (did you mean "
							"'max_iterations'?)"),
		std::string::npos) << r.output;
	r = viewer(base + " --rematch NoSuchMatcher");
	EXPECT_EQ(r.exitCode, 2) << r.output;
	EXPECT_NE(r.output.find("no matcher class 'NoSuchMatcher'"), std::string::npos) << r.output;
}

TEST(Viewer, StereoPageShowsTheRunsPictureAndTheSegmentStage)
{
	TempDir tmp;
	const std::string dir = tmp.file("stereo");
	const CommandResult run = runCommand(shellQuote(kRun) + " " +
		shellQuote(kSource + "/configs/stereo-moon-lab.ini") + " --out " + shellQuote(dir) +
		" -q 2>&1");
	ASSERT_EQ(run.exitCode, 0) << run.output;
	// Step 8 has a stereo pair and the run's picture (stereo_debug_every = 4).
	ASSERT_TRUE(fs::exists(dir + "/stereo_debug/000008.png"));
	CommandResult r = viewer(shellQuote(dir) + " --view stereo --step 8 --screenshot " +
		shellQuote(tmp.file("s.png")));
	ASSERT_EQ(r.exitCode, 0) << r.output;
	EXPECT_NE(r.output.find("segment stage: "), std::string::npos) << r.output;
	EXPECT_EQ(r.output.find("wrote no picture"), std::string::npos) << r.output;
	const cv::Mat img = cv::imread(tmp.file("s.png"));
	ASSERT_FALSE(img.empty());
	EXPECT_GT(pixelsOf(img, Hue::Green).size(), 500u) << "selected and supported segments";
	// A step without a pair says so.
	r = viewer(shellQuote(dir) + " --view stereo --step 9 --screenshot " +
		shellQuote(tmp.file("t.png")));
	ASSERT_EQ(r.exitCode, 0) << r.output;
	EXPECT_NE(r.output.find("no stereo pair at this step"), std::string::npos) << r.output;
}

TEST(Viewer, FollowsALiveRunAsItIsWritten)
{
	TempDir tmp;
	const unsigned short laser = freePort(), odo = freePort();
	const std::string out = tmp.file("live");
	// The viewer starts before the run, follows its staging folder while it
	// runs, and takes its screenshot 5 s in.
	const std::string script = emulatorCommand(tmp.file("emu"), laser, odo) +
		shellQuote(kViewer) + " " + shellQuote(out) + " --follow --screenshot " +
		shellQuote(tmp.file("f.png")) + " --screenshot-after 5 > " + shellQuote(tmp.file("v.txt")) +
		" 2>&1 & v=$!; " + shellQuote(kLive) + " " + liveArgs(laser, odo) + " --out " +
		shellQuote(out) + " --duration 6 > /dev/null 2>&1; wait $v; kill $emu";
	const CommandResult r = runCommand(
		"xvfb-run -a -s '-screen 0 1600x1200x24' bash -c " + shellQuote(script) + " 2>&1");
	ASSERT_EQ(r.exitCode, 0) << r.output;
	std::ifstream in(tmp.file("v.txt"));
	std::vector<size_t> counts;
	for (std::string line; std::getline(in, line);)
	{
		const auto at = line.find(".featloc-partial-");
		if (line.find("following ") == std::string::npos || at == std::string::npos) continue;
		counts.push_back(std::stoul(line.substr(line.rfind(": ") + 2)));
	}
	ASSERT_GE(counts.size(), 3u) << "the viewer saw the run grow at least three times";
	EXPECT_TRUE(std::is_sorted(counts.begin(), counts.end()));
	EXPECT_GT(counts.back(), counts.front());
	const cv::Mat img = cv::imread(tmp.file("f.png"));
	ASSERT_FALSE(img.empty());
	EXPECT_GT(pixelsOf(img, kTrajectory).size(), 20u) << "the path so far";
}

TEST(Viewer, LiveGuiOpensTheViewerOnTheRun)
{
	TempDir tmp;
	const unsigned short laser = freePort(), odo = freePort();
	const std::string out = tmp.file("live");
	// featloc-live --gui starts featloc-viewer --follow in its own process
	// (it stays after the run): the test checks it is running, then ends it.
	const std::string script = emulatorCommand(tmp.file("emu"), laser, odo) +
		shellQuote(kLive) +
		" " + liveArgs(laser, odo) + " --out " + shellQuote(out) + " --duration 3 --gui > " +
		shellQuote(tmp.file("l.txt")) + " 2>&1; kill $emu; " +
		"pid=$(sed -n 's/.*featloc-viewer (pid \\([0-9]*\\)).*/\\1/p' " +
		shellQuote(tmp.file("l.txt")) + "); kill -0 $pid && echo viewer-running; kill $pid";
	const CommandResult r = runCommand(
		"xvfb-run -a -s '-screen 0 1600x1200x24' bash -c " + shellQuote(script) + " 2>&1");
	std::ifstream in(tmp.file("l.txt"));
	const std::string live((std::istreambuf_iterator<char>(in)), {});
	EXPECT_NE(live.find("featloc-viewer (pid "), std::string::npos) << live;
	EXPECT_NE(r.output.find("viewer-running"), std::string::npos) << r.output << live;
}

TEST(Viewer, PlayAdvancesAtTheLogsOwnRate)
{
	TempDir tmp;
	const std::string dir = runInto(tmp.file("m"), "matcher");
	const CommandResult r = viewer(shellQuote(dir) + " --play --screenshot " +
		shellQuote(tmp.file("p.png")) + " --screenshot-after 2");
	ASSERT_EQ(r.exitCode, 0) << r.output;
	const auto at = r.output.find("(step ");
	ASSERT_NE(at, std::string::npos) << r.output;
	const int step = std::stoi(r.output.substr(at + 6));
	// 2 s of wall time at 1x is at most ~2.5 s of this ~10 Hz log (the
	// timer's ticks advance log time; a loaded machine ticks less often).
	EXPECT_GE(step, 3) << r.output;
	EXPECT_LE(step, 40) << r.output;
}

// Localization in a known map: the map the run used is drawn under the
// scans (MapCanvas::kKnownMap, pink), read again from summary.json's
// map_file; a run without a map has none.
TEST(Viewer, DrawsTheKnownMapOfALocalizationRun)
{
	TempDir dir;
	const std::string out = dir.file("inmap");
	const CommandResult r = runCommand(shellQuote(kRun) + " " + shellQuote(kConfig) + " " +
		shellQuote(kSource + "/rawlogs/sim/office.rawlog") + " --out " + shellQuote(out) +
		" -q --set Pipeline:estimator=ekf --set 'Pipeline:initial_pose=[2 8 0]' --set Localization:map=" +
		shellQuote(kSource + "/worlds/office.ini") + " --set Input:max_scans=60 2>&1");
	ASSERT_EQ(r.exitCode, 0) << r.output;
	auto pink = [](const cv::Mat& img) {
		size_t n = 0;
		for (int y = kMapTop; y < img.rows; y++)
			for (int x = 0; x < img.cols; x++)
			{
				const int b = img.at<cv::Vec3b>(y, x)[0], g = img.at<cv::Vec3b>(y, x)[1],
						  r = img.at<cv::Vec3b>(y, x)[2];
				n += r > b + 15 && b > g + 20 && r > g + 45 ? 1 : 0;
			}
		return n;
	};
	const cv::Mat withMap = screenshot(out, dir.file("map.png"), "--view map --size 1200x850");
	EXPECT_GT(pink(withMap), 1000u);
	const cv::Mat without = screenshot(runInto(dir.file("nomap"), "ekf"), dir.file("nomap.png"),
		"--view map --size 1200x850");
	EXPECT_LT(pink(without), 50u);
}
