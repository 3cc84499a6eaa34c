#include "featloc/app/EvalApp.h"

#include <mrpt/3rdparty/tclap/CmdLine.h>

#include <mrpt/core/bits_math.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>

#include "featloc/app/AppMain.h"
#include "featloc/app/UsageError.h"
#include "featloc/eval/PairedComparison.h"
#include "featloc/eval/TrajectoryEvaluator.h"
#include "featloc/eval/TrajectoryFile.h"
#include "featloc/eval/TrajectoryPlot.h"

namespace featloc
{
namespace
{
/** --paired-with: `a`'s RPE steps against `b`'s on the reference steps both
 * have (the same two reference poses), as JSON, and as text in `text`. A
 * step is off when its RPE exceeds featloc-bench's gross error (10 cm or
 * 2 deg). Throws UsageError when they share no step. */
nlohmann::json pairedSteps(const EvaluationReport& a, const EvaluationReport& b,
	const std::string& otherName, std::string& text)
{
	constexpr double kOffTrans = 0.10, kOffYaw = mrpt::DEG2RAD(2.0);
	std::map<std::pair<size_t, size_t>, const EvaluationReport::StepError*> ofB;
	for (const auto& s : b.rpeSteps) ofB[{s.from, s.to}] = &s;
	std::vector<double> ta, tb;
	std::vector<bool> ga, gb;
	for (const auto& s : a.rpeSteps)
	{
		const auto it = ofB.find({s.from, s.to});
		if (it == ofB.end()) continue;
		ta.push_back(s.translation);
		tb.push_back(it->second->translation);
		ga.push_back(s.translation > kOffTrans || s.rotation > kOffYaw);
		gb.push_back(it->second->translation > kOffTrans || it->second->rotation > kOffYaw);
	}
	if (ta.empty())
		throw UsageError("--paired-with '" + otherName +
			"': no step of the reference is covered by both estimates (other times?)");
	const auto c = PairedComparison::of(ta, ga, tb, gb);
	char buf[512];
	std::snprintf(buf, sizeof(buf),
		"\npaired with %s over %zu common steps:\n"
		"  RPE translation mean difference (this - other): %+.2f mm, 95%% interval (%+.2f, %+.2f)\n"
		"  steps off by > 10 cm or 2 deg: only this %zu, only the other %zu (McNemar p = %.2g)\n",
		otherName.c_str(), c.pairs, c.meanDiff * 1e3, c.ciLow * 1e3, c.ciHigh * 1e3, c.onlyA,
		c.onlyB, c.mcnemarP);
	text = buf;
	return {{"with", otherName}, {"steps", c.pairs}, {"rpe_trans_mean_diff_m", c.meanDiff},
		{"ci95_m", {c.ciLow, c.ciHigh}}, {"off_only_this", c.onlyA},
		{"off_only_other", c.onlyB}, {"mcnemar_p", c.mcnemarP}};
}
}  // namespace

int EvalApp::main(int argc, char** argv)
{
	TCLAP::CmdLine cmd(
		"featloc-eval: errors of an estimated trajectory against a reference. "
		"REFERENCE is a trajectory (TUM 't x y z qx qy qz qw', 't x y yaw' as "
		"MRPT's .GT.txt, MRPT robot paths 'x y z yaw pitch roll', KITTI 3x4 "
		"rows; '#' and '%' comments) or a relations file (Kummerle et al. "
		"2009: 't1 t2 x y z roll pitch yaw'); ESTIMATE a trajectory (TUM, 't x "
		"y yaw' or featloc poses_cov.txt). Reports ATE (RMSE after SE(2) "
		"alignment) and RPE of consecutive poses, or relation errors. With a "
		"single trajectory and --plot: draws it.",
		' ', "0.1");
	TCLAP::UnlabeledValueArg<std::string> argRef(
		"reference", "Reference trajectory or relations", true, "",
		"REFERENCE", cmd);
	TCLAP::UnlabeledValueArg<std::string> argEst(
		"estimate", "Estimated trajectory (absent: plot REFERENCE alone with --plot)", false,
		"", "ESTIMATE", cmd);
	TCLAP::ValueArg<std::string> argPlot(
		"p", "plot", "Write a PNG with both trajectories", false, "",
		"FILE.png", cmd);
	TCLAP::ValueArg<std::string> argNees(
		"", "nees-series",
		"Write the NEES of every pose ('t nees' rows; the estimate needs "
		"covariances, as poses_cov.txt)",
		false, "", "FILE", cmd);
	TCLAP::ValueArg<std::string> argPairedWith("", "paired-with",
		"Another estimate of the same run (another matcher, another setting): "
		"ESTIMATE against it step by step, on the reference's steps both cover: "
		"the mean RPE translation difference with its 95% block-bootstrap "
		"interval, and the steps only one of the two gets off by more than 10 cm "
		"or 2 deg, with McNemar's p (whatever the reference's own error, which "
		"both share, cancels)",
		false, "", "OTHER", cmd);
	TCLAP::SwitchArg argJson("j", "json", "Print JSON instead of a table", cmd);
	TCLAP::ValueArg<double> argMaxDt(
		"", "max-dt", "Max time difference when associating poses [s]", false,
		0.02, "SECONDS", cmd);
	TCLAP::SwitchArg argNoAlign("", "no-align",
		"ATE in the reference's frame, without aligning the estimate (localization in a known map)",
		cmd);
	TCLAP::ValueArg<std::string> argRefFormat(
		"", "reference-format",
		"auto | tum | txyyaw | poses_cov | relations | mrpt_path | kitti (default auto)", false,
		"auto", "FORMAT", cmd);
	int exitCode = 0;
	if (!parseCommandLine(cmd, argc, argv, exitCode)) return exitCode;
	if (!(argMaxDt.getValue() > 0)) throw UsageError("--max-dt must be > 0");

	TrajectoryFile::Format refFormat =
		TrajectoryFile::parseFormat(argRefFormat.getValue());
	if (refFormat == TrajectoryFile::Format::Auto)
		refFormat = TrajectoryFile::detect(argRef.getValue());
	if (!argEst.isSet())
	{
		// One trajectory: a picture of it, nothing to compare.
		if (!argPlot.isSet())
			throw UsageError("missing ESTIMATE (or give --plot FILE.png to draw REFERENCE alone)");
		const Trajectory t = TrajectoryFile::read(argRef.getValue(), refFormat);
		char title[160];
		std::snprintf(title, sizeof(title), "%zu poses", t.poses.size());
		TrajectoryPlot::write(argPlot.getValue(), Trajectory{}, t, {}, title);
		std::printf("%s: %zu poses (%s); plot in %s\n", argRef.getValue().c_str(),
			t.poses.size(), TrajectoryFile::formatDescription(refFormat).c_str(),
			argPlot.getValue().c_str());
		return 0;
	}
	const Trajectory est = TrajectoryFile::read(argEst.getValue());
	const TrajectoryEvaluator evaluator(argMaxDt.getValue(), !argNoAlign.getValue());

	EvaluationReport rep;
	if (refFormat == TrajectoryFile::Format::Relations)
	{
		if (argPlot.isSet())
			throw UsageError("--plot needs a reference trajectory, not relations");
		if (argNees.isSet())
			throw UsageError("--nees-series needs a reference trajectory, not relations");
		rep = evaluator.evaluateRelations(
			TrajectoryFile::readRelations(argRef.getValue()), est);
	}
	else
	{
		const Trajectory ref = TrajectoryFile::read(argRef.getValue(), refFormat);
		rep = evaluator.evaluate(ref, est);
		if (argNees.isSet())
		{
			if (!rep.hasNees)
				throw UsageError(
					"--nees-series: '" + argEst.getValue() +
					"' has no covariances (use featloc-run's poses_cov.txt)");
			rep.writeNeesSeries(argNees.getValue());
		}
		if (argPlot.isSet())
		{
			char title[160];
			std::snprintf(
				title, sizeof(title), "ATE rmse %.4f m, RPE mean %.4f m over %zu poses",
				rep.ate.rmse, rep.rpeTranslation.mean, rep.associated);
			TrajectoryPlot::write(argPlot.getValue(), ref, est, rep.alignment, title);
		}
	}
	std::string json = rep.toJson();
	std::string paired;
	if (argPairedWith.isSet())
	{
		if (refFormat == TrajectoryFile::Format::Relations)
			throw UsageError("--paired-with needs a reference trajectory, not relations");
		const Trajectory other = TrajectoryFile::read(argPairedWith.getValue());
		const EvaluationReport otherRep =
			evaluator.evaluate(TrajectoryFile::read(argRef.getValue(), refFormat), other);
		auto j = nlohmann::json::parse(json);
		j["paired"] = pairedSteps(rep, otherRep, argPairedWith.getValue(), paired);
		json = j.dump(2);
	}
	if (!argJson.getValue())
		std::printf("reference: %s (%s)\n", argRef.getValue().c_str(),
			TrajectoryFile::formatDescription(refFormat).c_str());
	std::printf("%s\n", argJson.getValue() ? json.c_str() : (rep.toText() + paired).c_str());
	return 0;
}
}  // namespace featloc
