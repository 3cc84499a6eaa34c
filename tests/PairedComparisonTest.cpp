#include <gtest/gtest.h>
#include <mrpt/random/RandomGenerators.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "featloc/eval/PairedComparison.h"

using featloc::PairedComparison;

namespace
{
// The normal-theory 95% interval's width for the mean of n iid values of
// standard deviation sd.
double iidWidth(double sd, size_t n) { return 2 * 1.96 * sd / std::sqrt(static_cast<double>(n)); }

double sampleSd(const std::vector<double>& v)
{
	double m = 0, s = 0;
	for (double x : v) m += x;
	m /= static_cast<double>(v.size());
	for (double x : v) s += (x - m) * (x - m);
	return std::sqrt(s / static_cast<double>(v.size() - 1));
}
}  // namespace

TEST(PairedComparison, McNemarsExactPValues)
{
	EXPECT_DOUBLE_EQ(PairedComparison::mcnemarExact(0, 0), 1.0);
	EXPECT_DOUBLE_EQ(PairedComparison::mcnemarExact(5, 5), 1.0);
	// 2 * P(X <= 0), X ~ B(10, 1/2)
	EXPECT_NEAR(PairedComparison::mcnemarExact(0, 10), 2.0 / 1024, 1e-12);
	EXPECT_NEAR(PairedComparison::mcnemarExact(10, 0), 2.0 / 1024, 1e-12);
	// 2 * (1 + 10 + 45 + 120) / 1024
	EXPECT_NEAR(PairedComparison::mcnemarExact(3, 7), 352.0 / 1024, 1e-12);
	// Large splits stay finite and tiny.
	const double p = PairedComparison::mcnemarExact(100, 300);
	EXPECT_GT(p, 0.0);
	EXPECT_LT(p, 1e-20);
}

// Both matchers' errors share a large reference error (sd 40 mm); A is 5 mm
// worse on every pair, each with 3 mm of its own noise. The means alone
// (about 60 mm, +-2 mm each) could not show it; paired, the interval is
// narrow, holds the 5 mm and excludes 0.
TEST(PairedComparison, TheSharedReferenceErrorCancels)
{
	mrpt::random::CRandomGenerator rng(3);
	const size_t n = 400;
	std::vector<double> a(n), b(n);
	std::vector<bool> ga(n, false), gb(n, false);
	for (size_t k = 0; k < n; k++)
	{
		const double shared = 0.060 + 0.040 * rng.drawGaussian1D_normalized();
		a[k] = shared + 0.005 + 0.003 * rng.drawGaussian1D_normalized();
		b[k] = shared + 0.003 * rng.drawGaussian1D_normalized();
	}
	const auto c = PairedComparison::of(a, ga, b, gb);
	EXPECT_EQ(c.pairs, n);
	EXPECT_NEAR(c.meanDiff, 0.005, 0.0006);
	EXPECT_LT(c.ciLow, c.meanDiff);
	EXPECT_GT(c.ciHigh, c.meanDiff);
	EXPECT_GT(c.ciLow, 0.0);
	EXPECT_LT(c.ciLow, 0.005);
	EXPECT_GT(c.ciHigh, 0.005);
	// sd of the difference 4.2 mm: about 0.8 mm wide for iid values.
	EXPECT_NEAR(c.ciHigh - c.ciLow, iidWidth(0.003 * std::sqrt(2.0), n), 0.3e-3);
}

// Consecutive pairs share a scan, so their errors run together: for
// strongly correlated differences (AR(1), phi 0.9) the block bootstrap's
// interval is much wider than the one that takes the pairs as independent.
TEST(PairedComparison, CorrelatedPairsWidenTheInterval)
{
	mrpt::random::CRandomGenerator rng(5);
	const size_t n = 600;
	std::vector<double> d(n), zero(n, 0.0);
	std::vector<bool> none(n, false);
	double x = 0;
	for (auto& v : d)
	{
		x = 0.9 * x + 0.01 * rng.drawGaussian1D_normalized();
		v = x;
	}
	const auto c = PairedComparison::of(d, none, zero, none);
	EXPECT_GT(c.ciHigh - c.ciLow, 1.8 * iidWidth(sampleSd(d), n));
	EXPECT_LT(c.ciLow, c.meanDiff);
	EXPECT_GT(c.ciHigh, c.meanDiff);
}

TEST(PairedComparison, CountsThePairsOnlyOneGetsGrosslyWrong)
{
	const std::vector<double> t(6, 0.01);
	const std::vector<bool> a = {true, true, false, true, false, false};
	const std::vector<bool> b = {true, false, false, false, true, false};
	const auto c = PairedComparison::of(t, a, t, b);
	EXPECT_EQ(c.onlyA, 2u);
	EXPECT_EQ(c.onlyB, 1u);
	EXPECT_NEAR(c.mcnemarP, 1.0, 1e-12);  // 2 * P(X <= 1 | n = 3) = 2 * 4 / 8
	EXPECT_DOUBLE_EQ(c.meanDiff, 0.0);
	EXPECT_DOUBLE_EQ(c.ciLow, 0.0);
	EXPECT_DOUBLE_EQ(c.ciHigh, 0.0);
}

TEST(PairedComparison, DifferentPairCountsAreAnError)
{
	const std::vector<double> t3(3, 0.0), t2(2, 0.0);
	const std::vector<bool> g3(3, false), g2(2, false);
	EXPECT_THROW(PairedComparison::of(t3, g3, t2, g2), std::invalid_argument);
	EXPECT_THROW(PairedComparison::of(t3, g2, t3, g3), std::invalid_argument);
	const auto empty = PairedComparison::of({}, {}, {}, {});
	EXPECT_EQ(empty.pairs, 0u);
	EXPECT_DOUBLE_EQ(empty.mcnemarP, 1.0);
}
