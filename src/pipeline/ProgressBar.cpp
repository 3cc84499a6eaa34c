#include "featloc/pipeline/ProgressBar.h"

#include <mrpt/system/progress.h>

#include <algorithm>
#include <cstdio>

namespace featloc
{
namespace
{
constexpr double kRedrawSeconds = 0.1;
/** Non-interactive: a line at least this often, whatever the progress. */
constexpr double kMaxQuietSeconds = 60.0;
/** Below 100 % until done(): the readers' look-ahead reaches the end of
 * the file a few entries before the last scan is processed. */
constexpr double kMaxRunningFraction = 0.99;

double secondsSince(std::chrono::steady_clock::time_point t)
{
	return std::chrono::duration<double>(std::chrono::steady_clock::now() - t)
		.count();
}
}  // namespace

ProgressBar::ProgressBar(std::ostream& out, bool interactive, double silentSeconds)
	: m_out(out),
	  m_interactive(interactive),
	  m_silentSeconds(silentSeconds),
	  m_start(std::chrono::steady_clock::now()),
	  m_lastPrint(m_start)
{
}

void ProgressBar::update(double fraction, size_t scans)
{
	const double elapsed = secondsSince(m_start);
	if (elapsed < m_silentSeconds) return;
	fraction = std::clamp(fraction, 0.0, kMaxRunningFraction);
	if (m_interactive)
	{
		if (m_printed && secondsSince(m_lastPrint) < kRedrawSeconds) return;
	}
	else
	{
		const int decile = static_cast<int>(fraction * 10);
		const bool overdue = m_printed && secondsSince(m_lastPrint) >= kMaxQuietSeconds;
		if (decile <= m_lastDecile && !overdue) return;
		m_lastDecile = std::max(m_lastDecile, decile);
	}
	print(fraction, scans, elapsed, false);
}

void ProgressBar::print(double fraction, size_t scans, double elapsed, bool final)
{
	char tail[128];
	const double eta =
		!final && fraction > 0.01 ? elapsed * (1 - fraction) / fraction : 0.0;
	std::snprintf(
		tail, sizeof(tail), " %3d%%  %zu scans  %.1f s  ETA %.0f s",
		static_cast<int>(fraction * 100), scans, elapsed, eta);
	if (m_interactive) m_out << '\r';
	m_out << mrpt::system::progress(fraction, 30) << tail;
	if (!m_interactive) m_out << '\n';
	m_out.flush();
	m_printed = true;
	m_lastPrint = std::chrono::steady_clock::now();
}

void ProgressBar::done(size_t scans)
{
	if (!m_printed || m_done) return;
	m_done = true;
	print(1.0, scans, secondsSince(m_start), true);
	if (m_interactive) m_out << '\n';
	m_out.flush();
}
}  // namespace featloc
