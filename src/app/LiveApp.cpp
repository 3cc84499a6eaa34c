#include "featloc/app/LiveApp.h"

#include <algorithm>
#include <spawn.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "featloc/app/AppMain.h"
#include "featloc/app/ConfigCommandLine.h"
#include "featloc/app/InterruptSignals.h"
#include "featloc/app/LiveStatusLine.h"
#include "featloc/app/RunConfiguration.h"
#include "featloc/app/RunOutputs.h"
#include "featloc/app/RunReport.h"
#include "featloc/app/UsageError.h"
#include "featloc/config/TrackedConfig.h"
#include "featloc/eval/ErrorStats.h"
#include "featloc/live/DriverQuirks.h"
#include "featloc/live/LiveSource.h"
#include "featloc/live/TcpOdometrySensor.h"
#include "featloc/output/ResultsFolder.h"
#include "featloc/output/SummaryJsonWriter.h"
#include "featloc/pipeline/Pipeline.h"
#include "featloc/registerClasses.h"

namespace featloc
{
namespace
{
/** featloc-viewer (beside this program) following `dir`, in its own
 * process: the window stays after the run ends. */
void openViewer(const std::string& dir)
{
	std::error_code ec;
	const auto self = std::filesystem::read_symlink("/proc/self/exe", ec);
	const std::string viewer = (self.parent_path() / "featloc-viewer").string();
	if (ec || !std::filesystem::exists(viewer))
		throw UsageError("--gui: featloc-viewer is not beside featloc-live (" + viewer + ")");
	std::vector<std::string> args = {viewer, dir, "--follow"};
	std::vector<char*> argv;
	for (auto& a : args) argv.push_back(a.data());
	argv.push_back(nullptr);
	pid_t pid = 0;
	if (posix_spawn(&pid, viewer.c_str(), nullptr, nullptr, argv.data(), environ) != 0)
		throw UsageError("--gui: cannot start " + viewer);
	std::fprintf(stderr, "featloc-live: featloc-viewer (pid %d) follows %s\n", pid, dir.c_str());
}

constexpr const char* kRecording = "live.rawlog";
constexpr const char* kLateRecording = "live-late.rawlog";

std::string liveJson(const LiveSource& source, const LiveStatusLine& status)
{
	nlohmann::json j;
	j["stopped_by"] = source.stopReason();
	j["seconds"] = source.secondsRunning();
	j["late_observations"] = source.lateObservations();
	for (const auto& s : source.report())
	{
		const LiveSensor::Status& st = s.status;
		j["sensors"].push_back({{"section", s.section}, {"driver", s.driver},
			{"received", st.received}, {"passed_on", s.passedOn}, {"late", s.late},
			{"restarts", st.failures}, {"rate_hz", s.rate}, {"last_error", st.lastError},
			{"driver_errors", st.driverErrors}, {"last_driver_error", st.lastDriverError},
			{"longest_gap_s", st.longestGap}, {"longest_gap_start_s", st.longestGapStart},
			{"stuck_drivers_left_behind", st.stuckDrivers}, {"replay_skipped", st.skipped},
			{"ended", st.ended}});
	}
	const ErrorStats l = ErrorStats::of(status.latencies());
	j["pose_latency_s"] = {
		{"count", l.count}, {"median", l.median}, {"p95", l.p95}, {"max", l.max}};
	const ErrorStats st = ErrorStats::of(status.startupLatencies());
	j["startup_pose_latency_s"] = {{"count", st.count}, {"max", st.max}};
	return j.dump();
}

void printLiveReport(const LiveSource& source, const LiveStatusLine& status)
{
	std::printf("live run stopped (%s) after %.1f s:\n", source.stopReason().c_str(),
		source.secondsRunning());
	for (const auto& s : source.report())
	{
		const LiveSensor::Status& st = s.status;
		std::printf("  [%s] %s: %zu observations (%.1f Hz), %zu passed on, %zu late",
			s.section.c_str(), s.driver.c_str(), st.received, s.rate, s.passedOn, s.late);
		std::printf(", longest gap %.2f s (at %.1f s)", st.longestGap, st.longestGapStart);
		if (st.failures)
			std::printf(", %zu driver restarts (last: %s)", st.failures, st.lastError.c_str());
		if (st.stuckDrivers)
			std::printf(", %zu driver threads left behind stuck in a call", st.stuckDrivers);
		if (st.driverErrors)
			std::printf(", %zu errors logged by the driver (last: %s)", st.driverErrors,
				st.lastDriverError.c_str());
		if (st.skipped)
			std::printf(", %zu frames of the recording skipped (overdue when read)", st.skipped);
		if (!st.ended.empty()) std::printf(", ended: %s", st.ended.c_str());
		std::printf("\n");
	}
	if (!status.latencies().empty())
	{
		const ErrorStats l = ErrorStats::of(status.latencies());
		std::printf("  pose latency (scan arrival to pose, every sensor up): median %.1f ms, p95 "
					"%.1f ms, max %.1f ms\n",
			l.median * 1e3, l.p95 * 1e3, l.max * 1e3);
	}
	if (!status.startupLatencies().empty())
		std::printf("  %zu scans arrived while the other sensors started; they waited up to %.0f "
					"ms for the slowest one's first observation\n",
			status.startupLatencies().size(), ErrorStats::of(status.startupLatencies()).max * 1e3);
}
}  // namespace

int LiveApp::main(int argc, char** argv)
{
	registerClasses();
	TCLAP::CmdLine cmd(
		"featloc-live: localize live from MRPT hardware drivers. CONFIG is a featloc ini "
		"plus sensor sections in rawlog-grabber's style ([Live] sensors = LASER ODOMETRY; "
		"[LASER] driver = CHokuyoURG and its keys; featloc's own TcpOdometrySensor reads a "
		"robot base's odometry over TCP). Everything received is recorded to "
		"DIR/live.rawlog (featloc-run replays it to the same poses). Ctrl-C or --duration "
		"stops; nothing received is lost.",
		' ', "0.1");
	TCLAP::UnlabeledValueArg<std::string> argConfig(
		"config", "The INI configuration file (see configs/live-emulator.ini)", false, "",
		"CONFIG", cmd);
	TCLAP::ValueArg<std::string> argOut(
		"o", "out", "Results folder; overrides [Output] dir", false, "", "DIR", cmd);
	TCLAP::ValueArg<double> argDuration("", "duration",
		"Stop after S seconds of data (from the first observation); default: until Ctrl-C",
		false, 0, "S", cmd);
	TCLAP::SwitchArg argGui("", "gui",
		"Open featloc-viewer on the run: it follows the results as they are written (and stays "
		"open after the run)",
		cmd);
	ConfigCommandLine config(cmd, "LASER:PORT_DIR=10941",
		"the reference configuration with a [Live] section");
	int exitCode = 0;
	if (!parseCommandLine(cmd, argc, argv, exitCode)) return exitCode;
	if (config.writeConfigIfAsked(
			"# featloc-live reference configuration: every featloc key with its default;\n"
			"# add one section per sensor (driver = ... and the driver's keys).\n",
			[](mrpt::config::CConfigFileBase& c) {
				RunConfiguration::defaults().save(c);
				LiveOptions live;
				live.sensors = {"LASER", "ODOMETRY"};
				live.saveToConfigFile(c, LiveOptions::kSection);
			}))
		return 0;
	if (argConfig.getValue().empty()) throw UsageError("missing CONFIG (the ini file)");
	if (argDuration.getValue() < 0) throw UsageError("--duration must be >= 0");
	// A device that hangs up must not kill the run (SIGPIPE on write).
	std::signal(SIGPIPE, SIG_IGN);
	InterruptSignals signals;

	TrackedConfig cfg;
	config.load(cfg, argConfig.getValue());
	const RunConfiguration rc = RunConfiguration::load(cfg);
	LiveOptions liveOptions;
	liveOptions.loadFromConfigFile(cfg, LiveOptions::kSection);
	ResultsFolder folder(argOut.isSet()
			? argOut.getValue()
			: cfg.resolvePath(OutputOptions::kSection, "dir", rc.output.dir));
	if (argGui.getValue()) openViewer(folder.dir());
	LiveSource source(cfg, liveOptions, folder.stagedFile(kRecording),
		folder.stagedFile(kLateRecording), argDuration.getValue(), &signals.flag());
	// Sensor sections not in [Live] sensors are kept for another run (as
	// rawlog-grabber does); their keys are not typos.
	std::vector<std::string> notStarted;
	for (const auto& section : LiveOptions::sensorSections(cfg))
		if (std::find(liveOptions.sensors.begin(), liveOptions.sensors.end(), section) ==
			liveOptions.sensors.end())
		{
			cfg.acceptSection(section);
			notStarted.push_back(section);
		}
	cfg.requireAllKeysRead();  // the drivers have read their keys by now

	RunOutputs outputs = RunOutputs::make(rc, folder, rc.estimator->keepsLandmarks(),
		!rc.evaluation.ground_truth.empty(), {kRecording, kLateRecording});
	RunReport::writeUsedConfig(cfg, folder.stagedFile("config_used.ini"));
	std::printf("featloc-live: %s\n  estimator: %s%s\n  results:   %s\n",
		source.description().c_str(), rc.estimator->name().c_str(),
		rc.estimator->usesScanMatcher() ? (", matcher " + rc.matcher->className()).c_str() : "",
		folder.dir().c_str());
	RunReport::printAbandoned(folder);
	for (const auto& section : notStarted)
		std::printf("  not started: [%s] (not in [Live] sensors)\n", section.c_str());
	for (const auto& section : liveOptions.sensors)
	{
		const std::string driver = cfg.read_string(section, "driver", "");
		if (const std::string q = DriverQuirks::describe(driver); !q.empty())
			std::printf("  [%s] %s\n", section.c_str(), q.c_str());
		if (DriverQuirks::replaysRecording(driver, cfg, section))
			std::printf("  [%s] %s replays %s: each frame is delivered when it comes due "
						"([Live] replay_clock = %s)\n",
				section.c_str(), driver.c_str(),
				cfg.read_string(section, "rawlog_file", "").c_str(),
				liveOptions.replay_clock.c_str());
	}
	std::printf("starting the drivers (each must answer within %.0f s)...\n",
		liveOptions.startup_timeout);
	std::fflush(stdout);
	// A device falling silent is a warning: said even with -q.
	source.setNotice([](const std::string& notice) {
		std::fprintf(stderr, "featloc-live: %s\n", notice.c_str());
	});
	source.start();	 // throws for a silent device: the old results stay
	if (signals.requested())
	{
		std::fprintf(stderr, "featloc-live: interrupted before the run started; nothing was written\n");
		return 128 + SIGINT;
	}
	std::printf("running: Ctrl-C stops%s\n",
		argDuration.getValue() > 0
			? (" (or after " + std::to_string(argDuration.getValue()) + " s)").c_str()
			: "");
	std::fflush(stdout);

	LiveStatusLine status(source, config.quiet() ? 0.0 : liveOptions.status_period, stderr);
	std::vector<RunOutput*> all = outputs.pointers();
	all.push_back(&status);
	RunStats stats;
	try
	{
		Pipeline pipeline(rc.input, rc.odometry, rc.pipeline, rc.estimator, rc.matcher);
		if (rc.mapLocalizer) pipeline.setMapLocalizer(rc.mapLocalizer);
		stats = pipeline.run(source, all);
		printLiveReport(source, status);
		RunReport::printSummary(stats);
		outputs.summary->addMember("live", liveJson(source, status));
		outputs.summary->finish(stats);
		// The ground truth is read after the run: the emulator writes it
		// while the run goes.
		std::optional<RunReport::Reference> reference;
		if (!rc.evaluation.ground_truth.empty()) reference = RunReport::readGroundTruth(cfg, rc);
		RunReport::evaluateAndPlot(rc, reference, folder, stats, *outputs.summary);
	}
	catch (...)
	{
		folder.publish();  // what was recorded and estimated is kept
		throw;
	}
	folder.publish();
	std::printf("results in %s:\n", folder.dir().c_str());
	for (const auto& f : outputs.names) std::printf("  %s\n", f.c_str());
	return 0;
}
}  // namespace featloc
