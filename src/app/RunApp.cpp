#include "featloc/app/RunApp.h"

#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/system/filesystem.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>

#include "featloc/app/AppMain.h"
#include "featloc/app/ConfigCommandLine.h"
#include "featloc/app/RunConfiguration.h"
#include "featloc/app/UsageError.h"
#include "featloc/config/TrackedConfig.h"
#include "featloc/core/ConfigError.h"
#include "featloc/estimators/PoseEstimatorFactory.h"
#include "featloc/eval/ErrorStats.h"
#include "featloc/eval/TrajectoryEvaluator.h"
#include "featloc/eval/TrajectoryFile.h"
#include "featloc/eval/TrajectoryPlot.h"
#include "featloc/output/EstimatedRawlogWriter.h"
#include "featloc/output/LandmarkTableWriter.h"
#include "featloc/output/PoseCovarianceWriter.h"
#include "featloc/output/ScanMapSceneWriter.h"
#include "featloc/output/SummaryJsonWriter.h"
#include "featloc/output/TumTrajectoryWriter.h"
#include "featloc/pipeline/Pipeline.h"
#include "featloc/registerClasses.h"

namespace featloc
{
namespace
{
std::string joinPath(const std::string& dir, const std::string& file)
{
	return (std::filesystem::path(dir) / file).string();
}

std::string sizeText(const std::string& path)
{
	std::error_code ec;
	const auto bytes = std::filesystem::file_size(path, ec);
	if (ec) return "?";
	char buf[32];
	std::snprintf(buf, sizeof(buf), "%.1f MB", static_cast<double>(bytes) / 1e6);
	return buf;
}

void printSummary(const RunStats& s)
{
	std::printf(
		"processed %zu scans from %zu entries in %.2f s", s.scans, s.entries,
		s.wallTime);
	if (s.invalidatedBeams)
		std::printf(" (%zu beams invalidated)", s.invalidatedBeams);
	std::printf("\n");
	if (s.stepsWithoutOdometry)
		std::printf(
			"  %zu steps had no odometry (zero-motion prior used)\n",
			s.stepsWithoutOdometry);
	if (s.landmarkObservations || s.landmarksInMap)
		std::printf(
			"  %zu range-bearing observations; %zu landmarks in the map at the end\n",
			s.landmarkObservations, s.landmarksInMap);
	if (s.matchesAttempted)
	{
		const ErrorStats t = ErrorStats::of(s.matchTimes);
		std::printf(
			"  %zu matches: %zu failed (%zu fell back to odometry); time per "
			"match mean %.2f ms, median %.2f ms, p95 %.2f ms\n",
			s.matchesAttempted, s.matchFailures, s.fallbacks, t.mean * 1e3,
			t.median * 1e3, t.p95 * 1e3);
		for (const auto& ex : s.failureExamples)
			std::printf("    failed: %s\n", ex.c_str());
		for (const auto& ex : s.rejectionExamples)
			std::printf("    not used: %s\n", ex.c_str());
	}
	if (!s.estimatorTimes.empty())
	{
		// Real-time factor at 10 Hz scans: 0.1 s per scan over the time taken.
		const ErrorStats e = ErrorStats::of(s.estimatorTimes);
		std::printf(
			"  estimator %s: mean %.1f us per step (matcher excluded; %.0fx real time at 10 Hz)\n",
			s.estimator.c_str(), e.mean * 1e6, e.mean > 0 ? 0.1 / e.mean : 0.0);
	}
}
}  // namespace

int RunApp::main(int argc, char** argv)
{
	registerClasses();
	TCLAP::CmdLine cmd(
		"featloc-run: estimate a robot trajectory from a rawlog (odometry + "
		"2-D laser scans). Relative paths inside the ini are relative to the "
		"ini file's folder.",
		' ', "0.1");
	// TCLAP allows only one optional unlabeled argument: CONFIG [RAWLOG]
	// are taken together and counted below.
	TCLAP::UnlabeledMultiArg<std::string> argFiles(
		"files",
		"CONFIG: the INI configuration file (see config.ini); RAWLOG "
		"(optional): the rawlog to process, overriding [Input] rawlog",
		false, "CONFIG [RAWLOG]", cmd);
	TCLAP::ValueArg<std::string> argOut(
		"o", "out", "Results folder; overrides [Output] dir", false, "", "DIR",
		cmd);
	ConfigCommandLine config(cmd,
		"ScanMatcher:class=featloc::IcpMatcher or --set "
		"ScanMatcher.IcpMatcher:maxIterations=50",
		"the full reference configuration (every section and key, defaults, units)");
	int exitCode = 0;
	if (!parseCommandLine(cmd, argc, argv, exitCode)) return exitCode;

	if (config.writeConfigIfAsked(
			"# featloc reference configuration: every key with its default.\n",
			[](mrpt::config::CConfigFileBase& c) { RunConfiguration::defaults().save(c); }))
		return 0;
	const auto& files = argFiles.getValue();
	if (files.empty()) throw UsageError("missing CONFIG (the ini file)");
	if (files.size() > 2)
		throw UsageError(
			"too many arguments: expected CONFIG [RAWLOG], got " +
			std::to_string(files.size()) + " files");
	const bool rawlogGiven = files.size() == 2;

	TrackedConfig cfg;
	config.load(cfg, files[0]);
	RunConfiguration rc = RunConfiguration::load(cfg);
	cfg.requireAllKeysRead();

	const std::string rawlog = rawlogGiven
		? files[1]
		: cfg.resolvePath(InputOptions::kSection, "rawlog", rc.input.rawlog);
	if (rawlog.empty())
		throw ConfigError(
			cfg.sourceName() +
			": no rawlog: give one on the command line or set [Input] rawlog");
	const std::string outDir = argOut.isSet()
		? argOut.getValue()
		: cfg.resolvePath(OutputOptions::kSection, "dir", rc.output.dir);
	std::error_code ec;
	std::filesystem::create_directories(outDir, ec);
	if (ec || !std::filesystem::is_directory(outDir))
		throw std::runtime_error(
			"cannot create results folder '" + outDir + "': " + ec.message());

	// Outputs.
	std::vector<std::unique_ptr<RunOutput>> outputs;
	outputs.push_back(
		std::make_unique<TumTrajectoryWriter>(joinPath(outDir, "trajectory.tum")));
	outputs.push_back(
		std::make_unique<PoseCovarianceWriter>(joinPath(outDir, "poses_cov.txt")));
	if (rc.output.write_rawlog)
		outputs.push_back(std::make_unique<EstimatedRawlogWriter>(
			joinPath(outDir, "estimated.rawlog"), rc.output.pose_label));
	if (rc.output.write_scene)
		outputs.push_back(std::make_unique<ScanMapSceneWriter>(
			joinPath(outDir, "map.3Dscene"), rc.output.scene_scan_decimation,
			rc.output.scene_ellipse_every));
	if (rc.pipeline.estimator == "ekf")
		outputs.push_back(
			std::make_unique<LandmarkTableWriter>(joinPath(outDir, "landmarks.txt")));
	std::vector<std::string> written;
	for (const auto& o : outputs) written.push_back(o->path());
	const std::string summaryPath = joinPath(outDir, "summary.json");
	const std::string usedConfig = joinPath(outDir, "config_used.ini");
	written.push_back(summaryPath);
	written.push_back(usedConfig);
	auto summary = std::make_unique<SummaryJsonWriter>(summaryPath, written);
	SummaryJsonWriter* summaryPtr = summary.get();
	outputs.push_back(std::move(summary));
	{
		std::ofstream f(usedConfig);
		f << "# effective configuration of this run (ini + --set)\n"
		  << cfg.content();
	}

	auto estimator = PoseEstimatorFactory::create(rc.pipeline.estimator, rc.ekf);
	std::printf(
		"featloc-run: %s (%s)\n  estimator: %s%s\n  results:   %s\n",
		rawlog.c_str(), sizeText(rawlog).c_str(), estimator->name().c_str(),
		estimator->usesScanMatcher()
			? (", matcher " + rc.matcher->className()).c_str()
			: "",
		outDir.c_str());
	std::fflush(stdout);

	Pipeline pipeline(
		rc.input, rc.odometry, rc.pipeline, std::move(estimator), rc.matcher);
	std::vector<RunOutput*> outs;
	for (auto& o : outputs) outs.push_back(o.get());
	ProgressBar progress(std::cerr, isatty(STDERR_FILENO) != 0);
	const RunStats stats =
		pipeline.run(rawlog, outs, config.quiet() ? nullptr : &progress);
	printSummary(stats);

	// The ini's ground truth belongs to the ini's rawlog: with another
	// rawlog on the command line it only applies when given with --set.
	const bool gtFromCommandLine =
		cfg.origin(EvaluationOptions::kSection, "ground_truth").rfind("--set", 0) == 0;
	const bool evaluate = !rc.evaluation.ground_truth.empty() &&
		(!rawlogGiven || gtFromCommandLine);
	if (!rc.evaluation.ground_truth.empty() && !evaluate)
		std::printf(
			"not evaluated: [Evaluation] ground_truth belongs to the ini's "
			"rawlog; give --set Evaluation:ground_truth=FILE for this one\n");
	if (evaluate)
	{
		const std::string gtPath = cfg.resolvePath(
			EvaluationOptions::kSection, "ground_truth",
			rc.evaluation.ground_truth);
		const Trajectory gt = TrajectoryFile::read(gtPath);
		// poses_cov.txt: the same poses with their covariances (NEES).
		const Trajectory est = TrajectoryFile::read(joinPath(outDir, "poses_cov.txt"));
		const TrajectoryEvaluator evaluator(rc.evaluation.max_time_difference);
		const EvaluationReport rep = evaluator.evaluate(gt, est);
		std::printf("against ground truth:\n%s", rep.toText().c_str());
		summaryPtr->writeWithEvaluation(stats, rep.toJson());
		if (rep.hasNees)
		{
			const std::string neesPath = joinPath(outDir, "nees.txt");
			rep.writeNeesSeries(neesPath);
			written.push_back(neesPath);
		}
		const std::string plot = joinPath(outDir, "trajectory.png");
		char title[128];
		std::snprintf(
			title, sizeof(title), "%s: ATE rmse %.3f m over %zu poses",
			stats.estimator.c_str(), rep.ate.rmse, rep.associated);
		TrajectoryPlot::write(plot, gt, est, rep.alignment, title);
		written.push_back(plot);
	}
	std::printf("results in %s:\n", outDir.c_str());
	for (const auto& f : written) std::printf("  %s\n", f.c_str());
	return 0;
}
}  // namespace featloc
