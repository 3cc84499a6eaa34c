// featloc-run with stereo landmarks as a user runs it (configs/stereo-moon-lab.ini
// on the bundled simulated paper scene): the outputs, the landmarks against
// the simulator's exact edges, the gain over odometry; and the errors for a
// stereo extractor without the EKF, an unknown class and a map that does
// not cover the view.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "support/CommandRunner.h"
#include "support/TempDir.h"

using featloc::test::CommandResult;
using featloc::test::runCommand;
using featloc::test::shellQuote;
using featloc::test::TempDir;

namespace
{
const std::string kRun = FEATLOC_RUN_EXE;
const std::string kSource = FEATLOC_SOURCE_DIR;
const std::string kConfig = kSource + "/configs/stereo-moon-lab.ini";

CommandResult run(const std::string& out, const std::string& sets)
{
	return runCommand(shellQuote(kRun) + " " + shellQuote(kConfig) + " -q --out " + shellQuote(out) + " " + sets);
}

/** Last row's (x, y) of a TUM or poses_cov file. */
std::pair<double, double> lastPosition(const std::string& file)
{
	std::ifstream in(file);
	std::string line, last;
	while (std::getline(in, line))
		if (!line.empty() && line[0] != '#') last = line;
	std::istringstream s(last);
	double t, x, y;
	s >> t >> x >> y;
	return {x, y};
}
}  // namespace

TEST(StereoRunApp, LocalizesOnTheSimulatedPaperSceneWithLandmarksOnTheTrueEdges)
{
	TempDir dir;
	const std::string out = dir.file("stereo"), odo = dir.file("odometry");
	const CommandResult r = run(out, "");
	ASSERT_EQ(r.exitCode, 0) << r.output;
	const CommandResult o = run(odo, "--set Pipeline:estimator=odometry --set StereoLandmarks:class=");
	ASSERT_EQ(o.exitCode, 0) << o.output;

	std::ifstream sj(out + "/summary.json");
	const auto s = nlohmann::json::parse(sj);
	const auto& st = s["stereo_landmarks"];
	EXPECT_EQ(st["pairs_processed"].get<int>(), 16);
	EXPECT_GT(st["landmarks_started"].get<int>(), 5);
	EXPECT_GT(st["observations_used"].get<int>(), 50);
	EXPECT_FALSE(std::filesystem::is_empty(out + "/stereo_debug"));

	// Every vertical landmark near a true edge of its wall (the simulator's
	// edges), within 3 sigma (+1 mm): at least 80% of them (a texture's
	// stripe is an edge the geometry does not list).
	std::map<std::string, std::vector<std::pair<double, double>>> edges;
	{
		std::ifstream in(kSource + "/rawlogs/stereo/moon-lab.edges.gt.txt");
		std::string line;
		while (std::getline(in, line))
		{
			if (line.empty() || line[0] == '#') continue;
			std::istringstream ls(line);
			std::string frame, t, object;
			double sPos, x, y;
			ls >> frame >> t >> object >> sPos >> x >> y;
			edges[object].emplace_back(x, y);
		}
	}
	std::ifstream lm(out + "/landmarks.txt");
	std::string line;
	size_t vertical = 0, onEdge = 0;
	while (std::getline(lm, line))
	{
		if (line.empty() || line[0] == '#') continue;
		std::istringstream ls(line);
		long long id;
		double x, y, cxx, cxy, cyy, lLow, lHigh, l, sx, sy;
		unsigned obsCount;
		std::string kind, plane;
		ls >> id >> x >> y >> cxx >> cxy >> cyy >> obsCount >> kind >> plane >> lLow >> lHigh >> l >> sx >> sy;
		ASSERT_EQ(kind, "vertical") << line;
		vertical++;
		EXPECT_GT(lHigh, lLow) << line;
		// On its wall's line (partition y = 4, whiteboard 6, lab wall 6.02):
		// eq. (17) leaves no freedom across it.
		EXPECT_LT(std::min({std::abs(y - 4.0), std::abs(y - 6.0), std::abs(y - 6.02)}), 2e-3) << line;
		double best = 1e9;
		for (const auto& [ex, ey] : edges[plane.substr(0, plane.find('#'))])
			best = std::min(best, std::hypot(x - ex, y - ey));
		if (best <= 3 * sx + 1e-3) onEdge++;
	}
	EXPECT_GT(vertical, 5u);
	EXPECT_GE(onEdge, 0.8 * static_cast<double>(vertical)) << onEdge << " of " << vertical;
	// Table 1 per pair: selected and not, with reasons.
	std::ifstream ft(out + "/stereo_features.txt");
	size_t rows = 0, nearBoundary = 0;
	while (std::getline(ft, line))
		if (!line.empty() && line[0] != '#')
		{
			rows++;
			nearBoundary += line.find("No -1 near boundary") != std::string::npos;
		}
	EXPECT_GT(rows, 50u);
	EXPECT_GT(nearBoundary, 5u);
	// The walls that observed the pose (featloc's wall observations), and
	// what the EKF did with each; summary.json counts them.
	std::ifstream wt(out + "/stereo_walls.txt");
	size_t wallRows = 0, wallsUsed = 0;
	while (std::getline(wt, line))
		if (!line.empty() && line[0] != '#')
		{
			wallRows++;
			wallsUsed += line.size() > 5 && line.compare(line.size() - 5, 5, " used") == 0;
			EXPECT_NE(line.find(" Wall."), std::string::npos) << line;
		}
	EXPECT_GT(wallRows, 5u);
	EXPECT_GT(wallsUsed, 0.8 * static_cast<double>(wallRows));
	const auto summary = nlohmann::json::parse(std::ifstream(out + "/summary.json"));
	EXPECT_EQ(summary["stereo_landmarks"]["wall_observations"].get<size_t>(), wallRows);
	EXPECT_EQ(summary["stereo_landmarks"]["wall_observations_used"].get<size_t>(), wallsUsed);

	// The final position: the true one is (0, 1.86) in the map's frame.
	const auto [xs, ys] = lastPosition(out + "/trajectory.tum");
	const auto [xo, yo] = lastPosition(odo + "/trajectory.tum");
	const double es = std::hypot(xs, ys - 1.86), eo = std::hypot(xo, yo - 1.86);
	EXPECT_LT(es, 0.5 * eo) << "stereo " << es << " m, odometry " << eo << " m";
}

TEST(StereoRunApp, StereoWithoutTheEkfOrWithAnUnknownClassIsAConfigError)
{
	TempDir dir;
	CommandResult r = run(dir.file("a"), "--set Pipeline:estimator=matcher");
	EXPECT_EQ(r.exitCode, 2) << r.output;
	EXPECT_NE(r.output.find("[StereoLandmarks]"), std::string::npos) << r.output;
	EXPECT_NE(r.output.find("estimator = ekf"), std::string::npos) << r.output;
	r = run(dir.file("b"), "--set StereoLandmarks:class=NoSuchExtractor");
	EXPECT_EQ(r.exitCode, 2) << r.output;
	EXPECT_NE(r.output.find("featloc::StableVerticalLandmarks"), std::string::npos) << r.output;
}

TEST(StereoRunApp, AMapThatDoesNotCoverTheViewIsAnErrorNamingIt)
{
	TempDir dir;
	const std::string map = dir.file("elsewhere.txt");
	std::ofstream(map) << "# a building 100 m away\n100 100 104 100\n";
	const CommandResult r = run(dir.file("c"), "--set StereoLandmarks.StableVerticalLandmarks:map=" + shellQuote(map));
	EXPECT_NE(r.exitCode, 0) << r.output;
	EXPECT_NE(r.output.find("elsewhere.txt"), std::string::npos) << r.output;
	EXPECT_NE(r.output.find("in view"), std::string::npos) << r.output;
	// What was estimated is kept.
	EXPECT_TRUE(std::filesystem::exists(dir.file("c/trajectory.tum")));
}
