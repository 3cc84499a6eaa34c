#pragma once
#include <chrono>
#include <cstddef>
#include <ostream>

namespace featloc
{
/** Progress of a long run on stderr. Silent for the first `silentSeconds`
 * (short runs print nothing). On a terminal, one line redrawn in place at
 * most ten times a second; otherwise (CI logs, pipes) one line per 10 % of
 * the input, and at least one a minute on a slow run.
 *
 * The fraction is what the source has really consumed (bytes of the file on
 * disk, compressed for .gz); since readers buffer ahead, 100 % is printed
 * only by done(), after the last scan, never while scans remain. */
class ProgressBar
{
   public:
	ProgressBar(std::ostream& out, bool interactive, double silentSeconds = 1.0);

	/** `fraction` of the input consumed, `scans` processed so far. */
	void update(double fraction, size_t scans);
	/** The last line, at 100 % with the final scan count (if anything was
	 * printed before). */
	void done(size_t scans);

   private:
	void print(double fraction, size_t scans, double elapsed, bool final);

	std::ostream& m_out;
	bool m_interactive;
	double m_silentSeconds;
	std::chrono::steady_clock::time_point m_start, m_lastPrint;
	bool m_printed = false;
	bool m_done = false;
	int m_lastDecile = -1;
};
}  // namespace featloc
