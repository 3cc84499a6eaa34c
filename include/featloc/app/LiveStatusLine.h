#pragma once
#include <chrono>
#include <cstdio>
#include <vector>

#include "featloc/output/RunOutput.h"

namespace featloc
{
class LiveSource;

/** featloc-live's console while it runs: every `period` seconds one line
 * with the run time, the latest pose, each sensor's rate, the late
 * observations and the p95 latency of the period's poses (from a scan's
 * arrival from its driver to its pose). Keeps every latency for the final report. */
class LiveStatusLine : public RunOutput
{
   public:
	LiveStatusLine(const LiveSource& source, double period, std::FILE* out);

	void onStep(const StepRecord& record) override;
	void finish(const RunStats&) override {}
	std::string path() const override { return {}; }

	/** [s] arrival-to-pose latency of every scan's pose, scans that
	 * arrived once every sensor was up (LiveSource::start() returned). */
	const std::vector<double>& latencies() const { return m_latencies; }
	/** [s] the same for the scans that arrived while the sensors were
	 * starting: they wait for the slowest device's first observation. */
	const std::vector<double>& startupLatencies() const { return m_startupLatencies; }

   private:
	const LiveSource& m_source;
	double m_period;
	std::FILE* m_out;
	std::chrono::steady_clock::time_point m_lastLine;
	std::vector<double> m_latencies, m_startupLatencies;
	size_t m_periodStart = 0;  //!< first latency of the current period
};
}  // namespace featloc
