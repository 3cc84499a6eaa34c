#include "featloc/eval/LineAgreement.h"

#include <Eigen/Dense>
#include <algorithm>
#include <limits>

namespace featloc
{
namespace
{
bool compatible(const WorldVerticalLine& p, const WorldVerticalLine& q)
{
	return p.polarity == q.polarity && std::min(p.zHigh, q.zHigh) > std::max(p.zLow, q.zLow);
}

/** For each line of `from`, the nearest compatible line of `to` (or -1). */
std::vector<long> nearest(const std::vector<WorldVerticalLine>& from, const std::vector<WorldVerticalLine>& to)
{
	std::vector<long> out(from.size(), -1);
	for (size_t i = 0; i < from.size(); i++)
	{
		double best = std::numeric_limits<double>::infinity();
		for (size_t j = 0; j < to.size(); j++)
		{
			if (!compatible(from[i], to[j])) continue;
			const double d = (from[i].xy - to[j].xy).squaredNorm();
			if (d < best)
			{
				best = d;
				out[i] = static_cast<long>(j);
			}
		}
	}
	return out;
}
}  // namespace

std::vector<LineAgreement::Pair> LineAgreement::pair(
	const std::vector<WorldVerticalLine>& a, const std::vector<WorldVerticalLine>& b)
{
	const auto ab = nearest(a, b), ba = nearest(b, a);
	std::vector<Pair> out;
	for (size_t i = 0; i < a.size(); i++)
	{
		if (ab[i] < 0 || ba[static_cast<size_t>(ab[i])] != static_cast<long>(i)) continue;
		Pair p;
		p.a = i;
		p.b = static_cast<size_t>(ab[i]);
		p.difference = b[p.b].xy - a[i].xy;
		p.mahalanobis2 = p.difference.dot((a[i].cov + b[p.b].cov).ldlt().solve(p.difference));
		out.push_back(p);
	}
	return out;
}
}  // namespace featloc
