#pragma once
#include <chrono>
#include <cstddef>
#include <ostream>

namespace featloc
{
/** Progress of a long run on stderr. Silent for the first second (short
 * runs print nothing). On a terminal, one line redrawn in place at most ten
 * times a second; otherwise (CI logs, pipes) one line per 10 %. */
class ProgressBar
{
   public:
	ProgressBar(std::ostream& out, bool interactive);

	/** `fraction` of the input consumed, `scans` processed so far. */
	void update(double fraction, size_t scans);
	/** Ends the line (if anything was printed). */
	void done(size_t scans);

   private:
	void print(double fraction, size_t scans, double elapsed);

	std::ostream& m_out;
	bool m_interactive;
	std::chrono::steady_clock::time_point m_start, m_lastPrint;
	bool m_printed = false;
	int m_lastDecile = -1;
	size_t m_lastScans = 0;
};
}  // namespace featloc
