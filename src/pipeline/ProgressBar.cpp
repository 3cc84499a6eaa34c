#include "featloc/pipeline/ProgressBar.h"

#include <mrpt/system/progress.h>

#include <cstdio>

namespace featloc
{
namespace
{
constexpr double kSilentSeconds = 1.0;
constexpr double kRedrawSeconds = 0.1;

double secondsSince(std::chrono::steady_clock::time_point t)
{
	return std::chrono::duration<double>(std::chrono::steady_clock::now() - t)
		.count();
}
}  // namespace

ProgressBar::ProgressBar(std::ostream& out, bool interactive)
	: m_out(out),
	  m_interactive(interactive),
	  m_start(std::chrono::steady_clock::now()),
	  m_lastPrint(m_start)
{
}

void ProgressBar::update(double fraction, size_t scans)
{
	const double elapsed = secondsSince(m_start);
	if (elapsed < kSilentSeconds) return;
	if (m_interactive)
	{
		if (m_printed && secondsSince(m_lastPrint) < kRedrawSeconds) return;
	}
	else
	{
		const int decile = static_cast<int>(fraction * 10);
		if (decile <= m_lastDecile) return;
		m_lastDecile = decile;
	}
	print(fraction, scans, elapsed);
}

void ProgressBar::print(double fraction, size_t scans, double elapsed)
{
	char tail[128];
	const double eta =
		fraction > 0.01 ? elapsed * (1 - fraction) / fraction : 0.0;
	std::snprintf(
		tail, sizeof(tail), " %3d%%  %zu scans  %.1f s  ETA %.0f s",
		static_cast<int>(fraction * 100 + 0.5), scans, elapsed, eta);
	if (m_interactive) m_out << '\r';
	m_out << mrpt::system::progress(fraction, 30) << tail;
	if (!m_interactive) m_out << '\n';
	m_out.flush();
	m_printed = true;
	m_lastScans = scans;
	m_lastPrint = std::chrono::steady_clock::now();
}

void ProgressBar::done(size_t scans)
{
	if (!m_printed) return;
	if (m_interactive)
	{
		print(1.0, scans, secondsSince(m_start));
		m_out << '\n';
	}
	else if (scans != m_lastScans)
	{
		// The compressed position can reach the end before the last
		// entries are decoded: the final line gives the real count.
		print(1.0, scans, secondsSince(m_start));
	}
	m_out.flush();
}
}  // namespace featloc
