#include "featloc/eval/ErrorStats.h"

#include <algorithm>
#include <cmath>

namespace featloc
{
namespace
{
/** Percentile q in [0,1] of sorted values, linear interpolation between
 * closest ranks (the default of numpy.percentile). */
double percentile(const std::vector<double>& sorted, double q)
{
	const double pos = q * static_cast<double>(sorted.size() - 1);
	const size_t lo = static_cast<size_t>(std::floor(pos));
	const size_t hi = std::min(lo + 1, sorted.size() - 1);
	return sorted[lo] + (pos - static_cast<double>(lo)) * (sorted[hi] - sorted[lo]);
}
}  // namespace

ErrorStats ErrorStats::of(std::vector<double> values)
{
	ErrorStats s;
	if (values.empty()) return s;
	std::sort(values.begin(), values.end());
	s.count = values.size();
	double sum = 0, sumSq = 0;
	for (double v : values)
	{
		sum += v;
		sumSq += v * v;
	}
	const double n = static_cast<double>(s.count);
	s.mean = sum / n;
	s.rmse = std::sqrt(sumSq / n);
	s.stddev = std::sqrt(std::max(0.0, sumSq / n - s.mean * s.mean));
	s.median = percentile(values, 0.5);
	s.p95 = percentile(values, 0.95);
	s.max = values.back();
	return s;
}
}  // namespace featloc
