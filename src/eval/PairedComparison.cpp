#include "featloc/eval/PairedComparison.h"

#include <mrpt/random/RandomGenerators.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace featloc
{
double PairedComparison::mcnemarExact(size_t b, size_t c)
{
	const size_t n = b + c, k = std::min(b, c);
	if (n == 0) return 1.0;
	// 2 * P(X <= k), X ~ Binomial(n, 1/2), summed in logs (n can be hundreds).
	double tail = 0;
	for (size_t i = 0; i <= k; i++)
		tail += std::exp(std::lgamma(n + 1.0) - std::lgamma(i + 1.0) - std::lgamma(n - i + 1.0) -
			static_cast<double>(n) * std::log(2.0));
	return std::min(1.0, 2 * tail);
}

PairedComparison PairedComparison::of(const std::vector<double>& transA,
	const std::vector<bool>& grossA, const std::vector<double>& transB,
	const std::vector<bool>& grossB)
{
	const size_t n = transA.size();
	if (grossA.size() != n || transB.size() != n || grossB.size() != n)
		throw std::invalid_argument("PairedComparison: the two matchers' pairs differ in number");
	PairedComparison out;
	out.pairs = n;
	if (n == 0) return out;
	std::vector<double> d(n);
	double sum = 0;
	for (size_t k = 0; k < n; k++)
	{
		d[k] = transA[k] - transB[k];
		sum += d[k];
		if (grossA[k] && !grossB[k]) out.onlyA++;
		if (grossB[k] && !grossA[k]) out.onlyB++;
	}
	out.meanDiff = sum / static_cast<double>(n);
	out.mcnemarP = mcnemarExact(out.onlyA, out.onlyB);

	// Moving-block bootstrap of the mean difference.
	const size_t block = std::min(kBlock, n);
	const size_t blocks = (n + block - 1) / block;
	mrpt::random::CRandomGenerator rng(1);
	std::vector<double> means(kResamples);
	for (auto& m : means)
	{
		double s = 0;
		size_t taken = 0;
		for (size_t b = 0; b < blocks; b++)
		{
			const size_t start = rng.drawUniform32bit() % (n - block + 1);
			for (size_t i = 0; i < block && taken < n; i++, taken++) s += d[start + i];
		}
		m = s / static_cast<double>(taken);
	}
	std::sort(means.begin(), means.end());
	const auto at = [&](double q)
	{ return means[static_cast<size_t>(std::lround(q * static_cast<double>(kResamples - 1)))]; };
	out.ciLow = at(0.025);
	out.ciHigh = at(0.975);
	return out;
}
}  // namespace featloc
