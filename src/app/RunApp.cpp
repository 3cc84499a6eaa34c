#include "featloc/app/RunApp.h"

#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>

#include "featloc/app/AppMain.h"
#include "featloc/app/ConfigCommandLine.h"
#include "featloc/app/InterruptSignals.h"
#include "featloc/app/RunOutputs.h"
#include "featloc/app/RunReport.h"
#include "featloc/app/RunConfiguration.h"
#include "featloc/app/UsageError.h"
#include "featloc/config/TrackedConfig.h"
#include "featloc/core/ConfigError.h"
#include "featloc/core/InputError.h"
#include "featloc/estimators/PoseEstimatorFactory.h"
#include "featloc/eval/TrajectoryFile.h"
#include "featloc/io/CarmenLogSource.h"
#include "featloc/io/EntrySource.h"
#include "featloc/live/LiveOptions.h"
#include "featloc/matchers/ScanMatcherFactory.h"
#include "featloc/output/ResultsFolder.h"
#include "featloc/output/SummaryJsonWriter.h"
#include "featloc/pipeline/Pipeline.h"
#include "featloc/registerClasses.h"

namespace featloc
{
namespace
{
std::string joinedNames(const std::vector<std::string>& names, const char* sep)
{
	std::string out;
	for (const auto& n : names) out += (out.empty() ? "" : sep) + n;
	return out;
}

/** The classes a user can choose, from the registries (not a hand list). */
std::string classesText()
{
	std::vector<std::string> aliases, classes;
	for (const auto& [alias, cls] : PoseEstimatorFactory::aliases())
	{
		aliases.push_back(alias);
		classes.push_back(cls);
	}
	return "estimators ([Pipeline] estimator): " + joinedNames(aliases, ", ") +
		" (short for " + joinedNames(classes, ", ") + ")" +
		"\nscan matchers ([ScanMatcher] class): " +
		joinedNames(ScanMatcherFactory::knownClassNames(), ", ") + "\n";
}

/** The ground truth named by [Evaluation] ground_truth, read now (a wrong
 * path fails before the first scan); for a CARMEN log without one, the
 * log's own corrected poses. The ini's ground truth belongs to the ini's
 * rawlog: with another input on the command line it only applies when
 * given with --set. */
std::optional<RunReport::Reference> loadReference(
	const TrackedConfig& cfg, const RunConfiguration& rc, bool inputOnCommandLine,
	const EntrySource& source)
{
	const std::string& gt = rc.evaluation.ground_truth;
	const bool gtFromCommandLine =
		cfg.origin(EvaluationOptions::kSection, "ground_truth").rfind("--set", 0) == 0;
	if (!gt.empty() && (!inputOnCommandLine || gtFromCommandLine))
		return RunReport::readGroundTruth(cfg, rc);
	if (!gt.empty())
		std::printf(
			"not evaluated against [Evaluation] ground_truth: it belongs to the ini's "
			"rawlog; give --set Evaluation:ground_truth=FILE for this input\n");
	if (const auto* carmen = dynamic_cast<const CarmenLogSource*>(&source))
	{
		RunReport::Reference r;
		for (const auto& s : carmen->scans())
		{
			TimedPose p;
			p.t = s.time;
			p.pose = s.pose;
			r.trajectory.poses.push_back(p);
		}
		r.trajectory.source = carmen->name();
		r.description = "the corrected poses in " + carmen->name();
		return r;
	}
	return std::nullopt;
}

/** featloc-run's command line: CONFIG [INPUT], --out, --list-classes and
 * the config options every app shares. */
struct RunCommandLine
{
	TCLAP::CmdLine cmd{
		"featloc-run: estimate a robot trajectory from a rawlog or a CARMEN log "
		"(odometry, 2-D laser scans, range-bearing landmarks). Relative paths inside "
		"the ini are relative to the ini file's folder. The results folder is "
		"replaced as a whole when the run ends; a run that cannot start leaves it "
		"untouched.\n" +
			classesText(),
		' ', "0.1"};
	// TCLAP allows only one optional unlabeled argument: CONFIG [INPUT] are
	// taken together and counted in files().
	TCLAP::UnlabeledMultiArg<std::string> argFiles{"files",
		"CONFIG: the INI configuration file (see config.ini); INPUT (optional): "
		"the rawlog (.rawlog, .rawlog.gz) or CARMEN log (.log, .log.gz) to "
		"process, overriding [Input] rawlog",
		false, "CONFIG [INPUT]", cmd};
	TCLAP::ValueArg<std::string> argOut{
		"o", "out", "Results folder; overrides [Output] dir", false, "", "DIR", cmd};
	TCLAP::SwitchArg argList{"", "list-classes",
		"List the estimators and scan-matcher classes that can be chosen, and exit", cmd};
	ConfigCommandLine config{cmd,
		"ScanMatcher:class=featloc::IcpMatcher or --set "
		"ScanMatcher.IcpMatcher:maxIterations=50",
		"the full reference configuration (every section and key, defaults, units)"};

	/** CONFIG and, if given, INPUT; anything else is a UsageError. */
	std::vector<std::string> files()
	{
		const auto& files = argFiles.getValue();
		for (const auto& f : files)
			if (f.size() > 1 && f[0] == '-') throw UsageError("unknown option '" + f + "'");
		if (files.empty()) throw UsageError("missing CONFIG (the ini file)");
		if (files.size() > 2)
			throw UsageError(
				"too many arguments: expected CONFIG [INPUT], got " +
				std::to_string(files.size()) + " files");
		return files;
	}
};

/** A featloc-live configuration replays its recording with featloc-run:
 * its [Live] section (still checked) and the sensor sections (with a
 * driver key) belong to featloc-live's drivers: their keys are not
 * "unknown" here. */
void acceptLiveSections(TrackedConfig& cfg)
{
	if (!cfg.sectionExists(LiveOptions::kSection)) return;
	LiveOptions live;
	live.loadFromConfigFile(cfg, LiveOptions::kSection);
	for (const auto& section : LiveOptions::sensorSections(cfg)) cfg.acceptSection(section);
}

/** Everything a run needs, checked before anything is written. */
struct PreparedRun
{
	TrackedConfig cfg;
	RunConfiguration rc;
	std::string inputPath;
	EntrySource::Ptr source;
	std::optional<RunReport::Reference> reference;
	std::unique_ptr<ResultsFolder> folder;
	RunOutputs outputs;
};

/** 1. The configuration, every key checked. 2. The input and the ground
 * truth, read before anything is written. 3. The results folder (the run
 * writes into its staging folder) and the outputs. */
void prepare(RunCommandLine& cl, const std::vector<std::string>& files, PreparedRun& run)
{
	cl.config.load(run.cfg, files[0]);
	run.rc = RunConfiguration::load(run.cfg);
	acceptLiveSections(run.cfg);
	run.cfg.requireAllKeysRead();

	const bool inputOnCommandLine = files.size() == 2;
	run.inputPath = inputOnCommandLine
		? files[1]
		: run.cfg.resolvePath(InputOptions::kSection, "rawlog", run.rc.input.rawlog);
	if (run.inputPath.empty())
		throw ConfigError(
			run.cfg.sourceName() +
			": no rawlog: give one on the command line or set [Input] rawlog");
	run.source = EntrySource::openFile(run.inputPath, run.rc.input);
	run.reference = loadReference(run.cfg, run.rc, inputOnCommandLine, *run.source);

	run.folder = std::make_unique<ResultsFolder>(cl.argOut.isSet()
			? cl.argOut.getValue()
			: run.cfg.resolvePath(OutputOptions::kSection, "dir", run.rc.output.dir));
	run.folder->requireOutside(run.inputPath, "input");
	if (run.reference && run.reference->trajectory.source != run.inputPath)
		run.folder->requireOutside(run.reference->trajectory.source, "ground truth");
	run.outputs = RunOutputs::make(
		run.rc, *run.folder, run.rc.estimator->keepsLandmarks(), run.reference.has_value());
	RunReport::writeUsedConfig(run.cfg, run.folder->stagedFile("config_used.ini"));
}

/** 4. The run, then the evaluation. Whatever happens, the results are
 * published (the staging folder takes the old folder's place). */
RunStats execute(PreparedRun& run, bool quiet, InterruptSignals& signals)
{
	RunStats stats;
	try
	{
		Pipeline pipeline(
			run.rc.input, run.rc.odometry, run.rc.pipeline, run.rc.estimator, run.rc.matcher);
		if (run.rc.mapLocalizer) pipeline.setMapLocalizer(run.rc.mapLocalizer);
		ProgressBar progress(std::cerr, isatty(STDERR_FILENO) != 0);
		stats = pipeline.run(
			*run.source, run.outputs.pointers(), quiet ? nullptr : &progress, &signals.flag());
		RunReport::printSummary(stats);
		try
		{
			RunReport::evaluateAndPlot(run.rc, run.reference, *run.folder, stats, *run.outputs.summary);
		}
		catch (const std::exception& e)
		{
			// summary.json must not say "ok" when the run exits with an error.
			stats.ok = false;
			stats.error = std::string("evaluation: ") + e.what();
			run.outputs.summary->finish(stats);
			throw;
		}
	}
	catch (...)
	{
		run.folder->publish();
		throw;
	}
	run.folder->publish();
	return stats;
}
}  // namespace

int RunApp::main(int argc, char** argv)
{
	registerClasses();
	RunCommandLine cl;
	int exitCode = 0;
	if (!parseCommandLine(cl.cmd, argc, argv, exitCode)) return exitCode;
	if (cl.argList.getValue())
	{
		std::printf("%s", classesText().c_str());
		return 0;
	}
	if (cl.config.writeConfigIfAsked(
			"# featloc reference configuration: every key with its default.\n",
			[](mrpt::config::CConfigFileBase& c) { RunConfiguration::defaults().save(c); }))
		return 0;
	const std::vector<std::string> files = cl.files();
	// From here Ctrl-C asks to stop: before the run starts, nothing is touched.
	InterruptSignals signals;

	PreparedRun run;
	prepare(cl, files, run);
	std::printf("featloc-run: %s (%s)\n  estimator: %s%s\n  results:   %s\n",
		run.inputPath.c_str(), run.source->description().c_str(),
		run.rc.estimator->name().c_str(),
		run.rc.estimator->usesScanMatcher() ? (", matcher " + run.rc.matcher->className()).c_str()
											: "",
		run.folder->dir().c_str());
	RunReport::printAbandoned(*run.folder);
	std::fflush(stdout);
	if (signals.requested())
	{
		std::fprintf(stderr, "featloc-run: interrupted before the run started; nothing was written\n");
		return 128 + SIGINT;
	}

	const RunStats stats = execute(run, cl.config.quiet(), signals);
	std::printf("results in %s:\n", run.folder->dir().c_str());
	for (const auto& f : run.outputs.names)
		if (std::ifstream(run.folder->finalFile(f))) std::printf("  %s\n", f.c_str());
	if (stats.interrupted)
	{
		std::printf("interrupted: the results hold the %zu steps processed\n", stats.steps);
		return 128 + SIGINT;
	}
	return 0;
}
}  // namespace featloc
