#pragma once
#include <string>
#include <utility>
#include <vector>

#include "featloc/output/RunOutput.h"

namespace featloc
{
/** summary.json: what ran (input, estimator, matcher), counts (entries,
 * scans, odometry, failures and fallbacks, invalidated beams), per-match
 * time (mean, median, p95, max) and iterations, total wall time, status
 * ("ok" or "error" with the message) and the list of files written. An
 * optional "evaluation" object (featloc-run with [Evaluation] ground_truth)
 * can be added by writeWithEvaluation(). */
class SummaryJsonWriter : public RunOutput
{
   public:
	SummaryJsonWriter(std::string path, std::vector<std::string> outputs);
	void onStep(const StepRecord&) override {}
	void finish(const RunStats& stats) override;
	std::string path() const override { return m_path; }

	/** Rewrites the file with an extra "evaluation" member (JSON text). */
	void writeWithEvaluation(
		const RunStats& stats, const std::string& evaluationJson);

	/** An extra top-level member (JSON text) in every later write, e.g.
	 * featloc-live's "live" report; finish() writes the file again. */
	void addMember(const std::string& key, const std::string& json);

   private:
	std::string m_path;
	std::vector<std::string> m_outputs;
	std::vector<std::pair<std::string, std::string>> m_members;
};
}  // namespace featloc
