#include "featloc/localization/LocalizationMapFile.h"
#include "featloc/gui/RunResultsLoader.h"

#include <mrpt/config/CConfigFile.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationRobotPose.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose2D.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "featloc/core/ExceptionText.h"
#include "featloc/core/InputError.h"
#include "featloc/eval/TrajectoryFile.h"
#include "featloc/io/RawlogReader.h"
#include "featloc/pipeline/StereoPairReader.h"

namespace featloc
{
namespace
{
namespace fs = std::filesystem;

void readScans(const std::string& path, const std::string& poseLabel, RunResults& r,
	const std::function<void(double)>& progress)
{
	RawlogReader reader(path);
	RawlogEntry entry;
	mrpt::obs::CObservation2DRangeScan::Ptr lastScan;
	size_t attached = 0;
	auto visit = [&](const mrpt::obs::CObservation::Ptr& obs) {
		if (auto scan = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(obs))
			lastScan = scan;
		else if (auto pose = std::dynamic_pointer_cast<mrpt::obs::CObservationRobotPose>(obs);
				 pose && pose->sensorLabel == poseLabel && lastScan)
		{
			const auto step = r.stepAt(mrpt::Clock::toDouble(pose->timestamp));
			if (step && r.stepAt(mrpt::Clock::toDouble(lastScan->timestamp)) == step)
			{
				r.steps[*step].scan = lastScan;
				attached++;
			}
			lastScan.reset();
		}
	};
	while (reader.next(entry))
	{
		if (auto sf = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(entry.object))
			for (const auto& obs : *sf) visit(obs);
		else if (auto obs = std::dynamic_pointer_cast<mrpt::obs::CObservation>(entry.object))
			visit(obs);
		if (progress && entry.index % 64 == 0) progress(reader.progress());
	}
	if (attached == 0)
		r.problems.push_back(path + ": no scan carries a '" + poseLabel +
			"' pose of this run: the map view has no scans");
}

// The stereo pairs, checked and decoded as featloc-run does (their image
// names were made absolute by the run), each with the run's own picture.
void readStereo(const std::string& path, RunResults& r)
{
	StereoPairReader reader(path);
	StereoPairReader::Pair pair;
	while (reader.next(pair))
	{
		const auto step = r.stepAt(mrpt::Clock::toDouble(pair.observation->timestamp));
		if (!step) continue;
		char name[32];
		std::snprintf(name, sizeof(name), "%06zu.png", *step);
		const fs::path picture = fs::path(path).parent_path() / "stereo_debug" / name;
		r.stereo.push_back({*step, pair.observation, pair.images,
			fs::exists(picture) ? picture.string() : std::string()});
	}
}

void readMatches(const std::string& path, RunResults& r)
{
	r.matches = MatchTableFile::read(path);
	for (size_t i = 0; i < r.matches.size(); i++)
	{
		const auto step = r.stepAt(r.matches[i].t);
		if (!step) continue;
		r.steps[*step].match = static_cast<int>(i);
		if (const auto ref = r.stepAt(r.matches[i].referenceT))
			r.steps[*step].reference = static_cast<int>(*ref);
	}
}

// Rows of numbers after '#' comments; throws InputError on a bad row.
std::vector<std::vector<double>> readNumberRows(const std::string& path, size_t minColumns)
{
	std::ifstream in(path);
	if (!in) throw InputError("cannot open '" + path + "'");
	std::vector<std::vector<double>> rows;
	std::string line;
	for (size_t n = 1; std::getline(in, line); n++)
	{
		if (line.empty() || line[0] == '#') continue;
		std::istringstream ss(line);
		std::vector<double> v;
		double x;
		while (v.size() < minColumns && ss >> x) v.push_back(x);
		if (v.size() < minColumns)
			throw InputError(path + ":" + std::to_string(n) + ": expected at least " +
				std::to_string(minColumns) + " numbers");
		rows.push_back(std::move(v));
	}
	return rows;
}

// The ground truth named by the run's config: as written (relative to the
// directory the run was started from), else relative to the results folder.
std::string findGroundTruth(const std::string& named, const std::string& folder)
{
	if (named.empty()) return "";
	if (fs::exists(named)) return named;
	const fs::path inFolder = fs::path(folder) / named;
	if (fs::exists(inFolder)) return inFolder.string();
	return "";
}
}  // namespace

RunResults RunResultsLoader::load(
	const std::string& folder, const std::function<void(double)>& progress)
{
	if (!fs::is_directory(folder))
		throw InputError("'" + folder + "' is not a results folder (not a directory)");
	RunResults r;
	r.folder = folder;
	auto file = [&](const char* name) { return (fs::path(folder) / name).string(); };
	auto optional = [&](const char* name, const auto& read) {
		const std::string path = file(name);
		if (!fs::exists(path))
		{
			r.problems.push_back(std::string(name) + " is missing");
			return;
		}
		try
		{
			read(path);
		}
		catch (const std::exception& e)
		{
			r.problems.push_back(std::string(name) + " could not be read: " + exceptionText(e));
		}
	};

	const std::string poses = file("poses_cov.txt");
	if (!fs::exists(poses))
		throw InputError("'" + folder + "' has no poses_cov.txt: not a featloc-run results folder");
	for (const TimedPose& p : TrajectoryFile::read(poses, TrajectoryFile::Format::PosesCov).poses)
		r.steps.push_back({p.t, p.pose, p.cov, nullptr, -1, -1});
	if (r.steps.empty()) throw InputError(poses + ": no poses (the run processed no step)");

	std::string poseLabel = "featloc_estimate", groundTruth, evaluatedReference, mapFile;
	LocalizationOptions localization;
	optional("config_used.ini", [&](const std::string& path) {
		mrpt::config::CConfigFile cfg(path);
		r.configPath = path;
		r.matcherClass = cfg.read_string("ScanMatcher", "class", "featloc::IcpMatcher");
		poseLabel = cfg.read_string("Output", "pose_label", poseLabel);
		groundTruth = cfg.read_string("Evaluation", "ground_truth", "");
		r.stereoExtractorClass = cfg.read_string("StereoLandmarks", "class", "");
		if (cfg.sectionExists(LocalizationOptions::kSection))
			localization.loadFromConfigFile(cfg, LocalizationOptions::kSection);
	});
	optional("summary.json", [&](const std::string& path) {
		std::ifstream in(path);
		const auto j = nlohmann::json::parse(in);
		r.estimator = j.value("estimator", "");
		if (j.contains("localization")) mapFile = j["localization"].value("map_file", "");
		if (j.contains("evaluation"))
			evaluatedReference = j["evaluation"].value("reference", "");
		if (j.contains("evaluation"))
			r.maxTimeDifference =
				j["evaluation"].value("max_time_difference_s", r.maxTimeDifference);
		if (j.contains("evaluation") && j["evaluation"].contains("alignment"))
		{
			const auto& a = j["evaluation"]["alignment"];
			const mrpt::poses::CPose2D align(a.value("x", 0.0), a.value("y", 0.0),
				mrpt::DEG2RAD(a.value("yaw_deg", 0.0)));
			r.groundTruthToEstimate = (mrpt::poses::CPose2D() - align).asTPose();
		}
	});
	optional("estimated.rawlog", [&](const std::string& path) {
		readScans(path, poseLabel, r, progress);
	});
	optional("matches.txt", [&](const std::string& path) { readMatches(path, r); });
	if (!r.stereoExtractorClass.empty())
		optional("estimated.rawlog", [&](const std::string& path) { readStereo(path, r); });
	if (r.estimator == "ekf")
		optional("landmarks.txt", [&](const std::string& path) {
			for (const auto& v : readNumberRows(path, 6))
				r.landmarks.push_back({v[1], v[2], v[3], v[4], v[5]});  // id -1: unnamed by the sensor
		});
	if (!mapFile.empty())
		try
		{
			localization.map = mapFile;	 // as the run resolved it
			r.mapCells = LocalizationMapFile::load(localization).occupiedCells();
		}
		catch (const std::exception& e)
		{
			r.problems.push_back("the localization map: " + exceptionText(e));
		}
	if (!groundTruth.empty())
	{
		// The file the run evaluated against (absolute in summary.json),
		// else the config's key as written.
		std::string gt = evaluatedReference.empty() || !fs::exists(evaluatedReference)
			? findGroundTruth(groundTruth, folder)
			: evaluatedReference;
		if (gt.empty())
			r.problems.push_back("the ground truth '" + groundTruth +
				"' named in config_used.ini was not found");
		else
			try
			{
				r.groundTruth = TrajectoryFile::read(gt);
			}
			catch (const std::exception& e)
			{
				r.problems.push_back("ground truth: " + exceptionText(e));
			}
		optional("nees.txt", [&](const std::string& path) {
			for (const auto& v : readNumberRows(path, 2)) r.nees.emplace_back(v[0], v[1]);
		});
	}
	return r;
}
}  // namespace featloc
