#include "featloc/app/EvalApp.h"

#include <mrpt/3rdparty/tclap/CmdLine.h>

#include <cstdio>

#include "featloc/app/AppMain.h"
#include "featloc/app/UsageError.h"
#include "featloc/eval/TrajectoryEvaluator.h"
#include "featloc/eval/TrajectoryFile.h"
#include "featloc/eval/TrajectoryPlot.h"

namespace featloc
{
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
	if (!argJson.getValue())
		std::printf("reference: %s (%s)\n", argRef.getValue().c_str(),
			TrajectoryFile::formatDescription(refFormat).c_str());
	std::printf("%s\n", argJson.getValue() ? rep.toJson().c_str() : rep.toText().c_str());
	return 0;
}
}  // namespace featloc
