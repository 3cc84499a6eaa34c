#pragma once
#include <memory>
#include <string>
#include <vector>

#include "featloc/output/RunOutput.h"

namespace featloc
{
class ResultsFolder;
class SummaryJsonWriter;
struct RunConfiguration;

/** Every output of a run (featloc-run, featloc-live), writing into the
 * results folder's staging folder, and the names of every file the folder
 * will hold (for summary.json and the console). */
struct RunOutputs
{
	std::vector<std::unique_ptr<RunOutput>> owned;
	SummaryJsonWriter* summary = nullptr;
	std::vector<std::string> names;

	std::vector<RunOutput*> pointers() const;

	/** The outputs the configuration asks for. `extraFiles`: files the
	 * run writes itself (featloc-live's recordings), listed in
	 * summary.json too. */
	static RunOutputs make(const RunConfiguration& rc, const ResultsFolder& folder,
		bool withLandmarks, bool withEvaluation, const std::vector<std::string>& extraFiles = {});
};
}  // namespace featloc
