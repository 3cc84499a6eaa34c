#pragma once
#include <optional>
#include <string>

#include "featloc/eval/TrajectoryFile.h"
#include "featloc/output/RunStats.h"

namespace featloc
{
class ResultsFolder;
class SummaryJsonWriter;
class TrackedConfig;
struct RunConfiguration;

/** What featloc-run and featloc-live report about a run: the console
 * summary, the evaluation against a reference (summary.json, nees.txt),
 * trajectory.png and config_used.ini. */
class RunReport
{
   public:
	/** The reference trajectory of a run and where it came from. */
	struct Reference
	{
		Trajectory trajectory;
		std::string description;
	};

	/** The trajectory named by [Evaluation] ground_truth (not empty), read
	 * whole; InputError naming the key when it cannot be read. */
	static Reference readGroundTruth(const TrackedConfig& cfg, const RunConfiguration& rc);

	static void printSummary(const RunStats& s);
	/** One console line per staging folder that a killed run left beside
	 * the results folder (ResultsFolder::abandoned()). */
	static void printAbandoned(const ResultsFolder& folder);

	/** The evaluation against the reference (summary.json, nees.txt) and
	 * trajectory.png, with or without a reference. */
	static void evaluateAndPlot(const RunConfiguration& rc,
		const std::optional<Reference>& reference, const ResultsFolder& folder,
		const RunStats& stats, SummaryJsonWriter& summary);

	/** config_used.ini: the effective configuration (ini + --set). */
	static void writeUsedConfig(const TrackedConfig& cfg, const std::string& path);
};
}  // namespace featloc
