#pragma once
#include <array>
#include <vector>

#include "featloc/matchers/CorrelationTables.h"
#include "featloc/scan/ScanPoints.h"
#include "featloc/scan/ScanSegment.h"

namespace featloc
{
/** What CorrelativeScanSearch builds for one reference scan, kept for the
 * next search on it: the lookup tables of its surfaces, the surfaces, the
 * sharp score's width, and the last branch and bound run on the tables with
 * what it was given.
 *
 * Why the branch and bound too: a matcher whose match fails hands the pair
 * to its fallback (PCM's and CF-IDC's is IDC), which searches the same
 * reference from the same guess with the same points, and the branch and
 * bound gives the same poses. On the Radish logs, where almost every pair
 * is searched, PCM's pairs each ran two searches and built two sets of
 * tables (doc/benchmarks.md, "Issue 15, twenty-seventh session"). */
class ReferenceTables
{
   public:
	CorrelationTables tables;
	std::vector<ScanSegment> segments;  //!< the reference's surfaces, as drawn
	double sharpSigma = 0;	//!< [m] the sharp score's width for this reference

	/** The key options of a build: resolution, hitSigma, sharpSigma. */
	using BuildOptions = std::array<double, 3>;
	/** Whether these are the tables of `reference` with levels up to
	 * `top` and built with `options`. */
	bool builtFor(const ScanPoints& reference, int top, const BuildOptions& options) const;
	/** Marks the tables as those of `reference` (after a build); forgets
	 * the last branch and bound. */
	void setBuiltFor(const ScanPoints& reference, int top, const BuildOptions& options);

	/** The last branch and bound's candidates if it had the same points,
	 * window and keep ratio, to the bit; null otherwise. */
	const std::vector<CorrelationTables::Candidate>* lastSearch(const std::vector<double>& px,
		const std::vector<double>& py, const CorrelationTables::Window& w, double keepRatio) const;
	/** Keeps a branch and bound's input and candidates for lastSearch(). */
	void rememberSearch(const std::vector<double>& px, const std::vector<double>& py,
		const CorrelationTables::Window& w, double keepRatio,
		const std::vector<CorrelationTables::Candidate>& found);

   private:
	ScanPoints m_reference;
	int m_top = -1;	 // -1: nothing built
	BuildOptions m_options{};
	bool m_hasSearch = false;
	std::vector<double> m_px, m_py;
	CorrelationTables::Window m_window;
	double m_keepRatio = 0;
	std::vector<CorrelationTables::Candidate> m_found;
};
}  // namespace featloc
