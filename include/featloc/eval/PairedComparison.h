#pragma once
#include <cstddef>
#include <vector>

namespace featloc
{
/** Two matchers compared pair by pair on the same scan pairs and guesses.
 *
 * On a real log the reference poses carry errors of their own (2-5 cm per
 * pair on the Radish logs: doc/benchmarks.md, "How much of the real logs'
 * NEES is the reference poses'"), which every matcher's error shares. Two
 * means of 40 and 42 mm, or two gross-error rates of 10.0% and 10.3%, say
 * nothing by themselves about which matcher is better. Paired, the shared
 * error cancels in the difference, and what is left is tested:
 *
 * - the mean difference of the two |t| errors, with a 95% confidence
 *   interval from a moving-block bootstrap (consecutive pairs share a
 *   scan, so their errors are not independent: blocks of kBlock pairs are
 *   resampled whole; percentile interval over kResamples, fixed seed);
 * - the pairs where only one of the two is grossly wrong in what the
 *   pipeline uses (ScanPairBenchmark::PairOutcome::error; a failure at its
 *   guess), with McNemar's exact two-sided p-value: the chance of a split
 *   at least as uneven if either matcher were as likely as the other to be
 *   the one that is wrong. */
struct PairedComparison
{
	static constexpr size_t kBlock = 10;  //!< pairs per bootstrap block
	static constexpr size_t kResamples = 4000;

	size_t pairs = 0;
	/** mean(|t| error of A - |t| error of B) [m] and its 95% interval. */
	double meanDiff = 0, ciLow = 0, ciHigh = 0;
	/** Pairs grossly wrong for A and not for B, and the other way round. */
	size_t onlyA = 0, onlyB = 0;
	double mcnemarP = 1;  //!< exact two-sided, 1 when onlyA + onlyB == 0

	/** A's and B's |t| errors [m] and gross flags, pair by pair (the same
	 * length; throws std::invalid_argument otherwise). */
	static PairedComparison of(const std::vector<double>& transA, const std::vector<bool>& grossA,
		const std::vector<double>& transB, const std::vector<bool>& grossB);

	/** Exact two-sided binomial (p = 1/2) test of a split b : c. */
	static double mcnemarExact(size_t b, size_t c);
};
}  // namespace featloc
