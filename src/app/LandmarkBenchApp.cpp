#include "featloc/app/LandmarkBenchApp.h"

#include <mrpt/config/CConfigFile.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/obs/CRawlog.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt/slam/CRangeBearingKFSLAM2D.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "featloc/app/AppMain.h"
#include "featloc/app/ConfigCommandLine.h"
#include "featloc/app/RunConfiguration.h"
#include "featloc/app/UsageError.h"
#include "featloc/config/TrackedConfig.h"
#include "featloc/core/InputError.h"
#include "featloc/estimators/PoseEstimatorFactory.h"
#include "featloc/eval/ErrorStats.h"
#include "featloc/io/RawlogReader.h"
#include "featloc/pipeline/StepAssembler.h"
#include "featloc/registerClasses.h"

namespace featloc
{
namespace
{
using Clock = std::chrono::steady_clock;

double since(Clock::time_point t0)
{
	return std::chrono::duration<double>(Clock::now() - t0).count();
}

/** One method's run: its path (one pose per step), its landmarks by
 * identity, and the filter's time per step. */
struct MethodRun
{
	std::string name;
	std::vector<mrpt::poses::CPose2D> path;
	std::map<int64_t, mrpt::math::TPoint2D> landmarks;
	size_t landmarksInState = 0;
	std::vector<double> stepTimes;	//!< [s]
	bool stoppedEarly = false;	//!< the time budget ran out
};

/** kf-slam's ground-truth landmark file: x y z ... with the id in column 7. */
std::map<int64_t, mrpt::math::TPoint2D> readLandmarkTruth(const std::string& path)
{
	std::ifstream in(path);
	if (!in) throw InputError("cannot read landmark ground truth '" + path + "'");
	std::map<int64_t, mrpt::math::TPoint2D> out;
	std::string line;
	for (size_t lineNo = 1; std::getline(in, line); lineNo++)
	{
		if (line.find_first_not_of(" \t\r") == std::string::npos || line[0] == '%' ||
			line[0] == '#')
			continue;
		std::istringstream ss(line);
		std::vector<double> v;
		for (double x; ss >> x;) v.push_back(x);
		if (v.size() < 7)
			throw InputError(
				"landmark ground truth '" + path + "' line " + std::to_string(lineNo) +
				": expected 'x y z ... id' with the id in column 7");
		out[static_cast<int64_t>(v[6])] = {v[0], v[1]};
	}
	return out;
}

void writePath(const std::string& file, const std::vector<mrpt::poses::CPose2D>& path)
{
	std::ofstream f(file);
	f << "% x y z yaw pitch roll (MRPT robot path: one row per step, no times)\n";
	f.precision(9);
	for (const auto& p : path) f << p.x() << " " << p.y() << " 0 " << p.phi() << " 0 0\n";
	if (!f) throw std::runtime_error("cannot write '" + file + "'");
}

void writeLandmarks(const std::string& file, const MethodRun& r)
{
	std::ofstream f(file);
	f << "# id x y\n";
	f.precision(9);
	for (const auto& [id, p] : r.landmarks) f << id << " " << p.x << " " << p.y << "\n";
	if (!f) throw std::runtime_error("cannot write '" + file + "'");
}

MethodRun runFeatloc(const RunConfiguration& rc, const std::string& rawlog)
{
	MethodRun r;
	r.name = "featloc " + rc.estimator->className();
	RawlogReader reader(rawlog);
	StepAssembler assembler(rc.input, rc.odometry, rawlog);
	PoseEstimator& est = *rc.estimator;
	std::vector<StepSource> used;
	std::vector<EstimationStep> ready;
	RawlogEntry e;
	auto process = [&](const EstimationStep& s) {
		const auto t0 = Clock::now();
		if (s.index == 0)
			est.start(rc.pipeline.initialPose(), s);
		else
			est.process(s, nullptr);
		r.stepTimes.push_back(since(t0));
		r.path.push_back(est.pose().mean);
	};
	while (reader.next(e))
	{
		ready.clear();
		assembler.push(e, used, ready);
		for (const auto& s : ready) process(s);
	}
	ready.clear();
	assembler.finish(ready);
	for (const auto& s : ready) process(s);
	const auto lms = est.landmarks();
	r.landmarksInState = lms.size();
	for (const auto& l : lms) r.landmarks[l.id] = {l.mean.x(), l.mean.y()};
	return r;
}

MethodRun runMrpt(const std::string& mrptIni, const std::string& rawlog, double maxSeconds)
{
	MethodRun r;
	r.name = "MRPT CRangeBearingKFSLAM2D";
	mrpt::slam::CRangeBearingKFSLAM2D slam;
	slam.loadOptions(mrpt::config::CConfigFile(mrptIni));
	slam.KF_options.verbosity_level = mrpt::system::LVL_ERROR;
	mrpt::io::CFileGZInputStream file(rawlog);
	auto arch = mrpt::serialization::archiveFrom(file);
	mrpt::obs::CActionCollection::Ptr action;
	mrpt::obs::CSensoryFrame::Ptr sf;
	size_t entry = 0;
	// kf-slam's reading: action/observation pairs; its initial pose, before
	// the first pair, is the origin.
	r.path.emplace_back();
	const auto start = Clock::now();
	while (mrpt::obs::CRawlog::readActionObservationPair(arch, action, sf, entry))
	{
		if (maxSeconds > 0 && since(start) > maxSeconds)
		{
			r.stoppedEarly = true;
			break;
		}
		const auto t0 = Clock::now();
		slam.processActionObservation(action, sf);
		r.stepTimes.push_back(since(t0));
		mrpt::poses::CPosePDFGaussian p;
		slam.getCurrentRobotPose(p);
		r.path.push_back(p.mean);
	}
	mrpt::poses::CPosePDFGaussian robot;
	std::vector<mrpt::math::TPoint2D> lms;
	std::map<unsigned int, mrpt::maps::CLandmark::TLandmarkID> ids;
	mrpt::math::CVectorDouble x;
	mrpt::math::CMatrixDouble P;
	slam.getCurrentState(robot, lms, ids, x, P);
	r.landmarksInState = lms.size();
	for (size_t i = 0; i < lms.size(); i++)
	{
		// A landmark without identity gets a negative key of its own (never
		// in the ground truth).
		const auto it = ids.find(static_cast<unsigned>(i));
		const int64_t key =
			it != ids.end() ? static_cast<int64_t>(it->second) : -1 - static_cast<int64_t>(i);
		r.landmarks[key] = lms[i];
	}
	return r;
}
}  // namespace

int LandmarkBenchApp::main(int argc, char** argv)
{
	registerClasses();
	TCLAP::CmdLine cmd(
		"featloc-bench-landmarks: featloc's EKF and MRPT's CRangeBearingKFSLAM2D (the filter "
		"of MRPT's kf-slam) on the same odometry + range-bearing log: time per step, "
		"landmarks, landmark errors; writes both paths for featloc-eval.",
		' ', "0.1");
	TCLAP::UnlabeledValueArg<std::string> argConfig(
		"config", "featloc INI ([Odometry], [Ekf], ...)", true, "", "CONFIG", cmd);
	TCLAP::UnlabeledValueArg<std::string> argRawlog(
		"rawlog", "Format #1 rawlog with actions and CObservationBearingRange", true, "",
		"RAWLOG", cmd);
	TCLAP::ValueArg<std::string> argMrpt("", "mrpt-config",
		"MRPT kf-slam ini for CRangeBearingKFSLAM2D", false,
		"/usr/share/mrpt/config_files/kf-slam/EKF-SLAM_test_2d.ini", "INI", cmd);
	TCLAP::ValueArg<double> argMaxSeconds("", "mrpt-max-seconds",
		"Stop MRPT's filter after this long (its time per step grows with the square of "
		"the landmarks; 0: no limit)",
		false, 300, "S", cmd);
	TCLAP::ValueArg<std::string> argTruth("", "landmarks-truth",
		"Ground-truth landmarks (kf-slam format, id in column 7)", false, "", "FILE", cmd);
	TCLAP::ValueArg<std::string> argOut("o", "out", "Folder for the paths and maps", false, "",
		"DIR", cmd);
	TCLAP::ValueArg<std::string> argName("", "name", "Data name in the table", false, "",
		"NAME", cmd);
	TCLAP::SwitchArg argHeader("", "header", "Print the Markdown table header", cmd);
	ConfigCommandLine config(cmd, "Ekf:data_association=nearest", "");
	int exitCode = 0;
	if (!parseCommandLine(cmd, argc, argv, exitCode)) return exitCode;

	TrackedConfig cfg;
	config.load(cfg, argConfig.getValue());
	RunConfiguration rc = RunConfiguration::load(cfg);
	cfg.requireAllKeysRead();
	// featloc's landmark filter whatever [Pipeline] estimator says; its
	// parameters from [Ekf].
	rc.estimator = PoseEstimatorFactory::createFromConfig(cfg, "ekf");
	if (!std::filesystem::is_regular_file(argMrpt.getValue()))
		throw InputError("MRPT config '" + argMrpt.getValue() + "' not found");
	const std::string rawlog = argRawlog.getValue();
	std::map<int64_t, mrpt::math::TPoint2D> truth;
	if (argTruth.isSet()) truth = readLandmarkTruth(argTruth.getValue());

	std::vector<MethodRun> runs{runFeatloc(rc, rawlog), runMrpt(argMrpt.getValue(), rawlog, argMaxSeconds.getValue())};

	const std::string name = argName.isSet()
		? argName.getValue()
		: std::filesystem::path(rawlog).filename().string();
	if (argHeader.getValue())
	{
		std::printf(
			"| data | method | steps | landmarks in state | time/step mean [us] | median [us] "
			"| p95 [us] | last quarter mean [us] | landmark error mean [mm] | max [mm] |\n");
		std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
	}
	for (const auto& r : runs)
	{
		const ErrorStats t = ErrorStats::of(r.stepTimes);
		const std::vector<double> lastQuarter(
			r.stepTimes.begin() + static_cast<long>(r.stepTimes.size() * 3 / 4), r.stepTimes.end());
		const ErrorStats q = ErrorStats::of(lastQuarter);
		std::vector<double> errors;
		for (const auto& [id, p] : r.landmarks)
			if (truth.count(id)) errors.push_back(std::hypot(p.x - truth[id].x, p.y - truth[id].y));
		const ErrorStats le = ErrorStats::of(errors);
		std::printf("| %s | %s | %zu%s | %zu | %.1f | %.1f | %.1f | %.1f | ", name.c_str(),
			r.name.c_str(), r.stepTimes.size(), r.stoppedEarly ? " (time budget ran out)" : "",
			r.landmarksInState, t.mean * 1e6, t.median * 1e6,
			t.p95 * 1e6, q.mean * 1e6);
		if (errors.empty())
			std::printf("- | - |\n");
		else
			std::printf("%.2f | %.2f |\n", le.mean * 1e3, le.max * 1e3);
	}
	if (argOut.isSet())
	{
		std::filesystem::create_directories(argOut.getValue());
		const std::string dir = argOut.getValue() + "/";
		writePath(dir + "featloc_path.txt", runs[0].path);
		writePath(dir + "mrpt_path.txt", runs[1].path);
		writeLandmarks(dir + "featloc_landmarks.txt", runs[0]);
		writeLandmarks(dir + "mrpt_landmarks.txt", runs[1]);
	}
	return 0;
}
}  // namespace featloc
