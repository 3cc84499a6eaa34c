#include "featloc/app/LiveStatusLine.h"

#include <mrpt/core/bits_math.h>

#include "featloc/eval/ErrorStats.h"
#include "featloc/live/LiveSource.h"

namespace featloc
{
LiveStatusLine::LiveStatusLine(const LiveSource& source, double period, std::FILE* out)
	: m_source(source), m_period(period), m_out(out), m_lastLine(std::chrono::steady_clock::now())
{
}

void LiveStatusLine::onStep(const StepRecord& record)
{
	const auto now = std::chrono::steady_clock::now();
	if (record.step.scan)
		if (const auto arrival = m_source.arrivalOf(record.step.source))
		{
			const auto running = m_source.runningSince();
			(running && *arrival >= *running ? m_latencies : m_startupLatencies)
				.push_back(std::chrono::duration<double>(now - *arrival).count());
		}
	if (m_period <= 0 || std::chrono::duration<double>(now - m_lastLine).count() < m_period)
		return;
	m_lastLine = now;
	const auto& p = record.pose.mean;
	std::fprintf(m_out, "live %6.1f s | pose %.3f %.3f %.1f deg |", m_source.secondsRunning(),
		p.x(), p.y(), mrpt::RAD2DEG(p.phi()));
	for (const auto& s : m_source.report())
		std::fprintf(m_out, " %s %.1f Hz%s |", s.section.c_str(), s.rate,
			s.status.failures
				? (" (" + std::to_string(s.status.failures) + " restarts)").c_str()
				: "");
	std::fprintf(m_out, " late %zu", m_source.lateObservations());
	// Over this period only: sorting the whole run's latencies on the
	// pipeline thread every period would grow with the run.
	const std::vector<double> recent(
		m_latencies.begin() + static_cast<std::ptrdiff_t>(m_periodStart), m_latencies.end());
	if (!recent.empty())
		std::fprintf(m_out, " | latency p95 %.1f ms", ErrorStats::of(recent).p95 * 1e3);
	m_periodStart = m_latencies.size();
	std::fprintf(m_out, "\n");
	std::fflush(m_out);
}
}  // namespace featloc
