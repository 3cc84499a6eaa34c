#include "featloc/ekf/JointCompatibilityBranchAndBound.h"

#include <algorithm>
#include <limits>

namespace featloc
{
namespace
{
/** The search is exponential in the worst case (many observations, each
 * compatible with many landmarks); past this many hypotheses the best one
 * found stands. */
constexpr size_t kMaxNodes = 200000;
}  // namespace

JointCompatibilityBranchAndBound::Pairing JointCompatibilityBranchAndBound::solve(
	const std::vector<std::vector<size_t>>& candidates, const JointDistance& jointDistance,
	const Gate& gate)
{
	const size_t n = candidates.size();
	Pairing best(n, -1), current(n, -1);
	size_t bestPairs = 0;
	double bestDistance = std::numeric_limits<double>::infinity();
	std::vector<std::pair<size_t, size_t>> pairs;  // the current hypothesis
	std::vector<char> used;

	// Observations that can still pair, from i on (for the bound).
	std::vector<size_t> pairableFrom(n + 1, 0);
	for (size_t i = n; i-- > 0;)
		pairableFrom[i] = pairableFrom[i + 1] + (candidates[i].empty() ? 0 : 1);

	size_t nodes = 0;
	std::function<void(size_t, double)> search = [&](size_t i, double distance) {
		if (pairs.size() + pairableFrom[i] < bestPairs) return;	 // cannot win
		if (++nodes > kMaxNodes) return;  // the best found so far stands
		if (i == n)
		{
			if (pairs.size() > bestPairs || (pairs.size() == bestPairs && distance < bestDistance))
			{
				best = current;
				bestPairs = pairs.size();
				bestDistance = distance;
			}
			return;
		}
		for (size_t lm : candidates[i])
		{
			if (lm >= used.size()) used.resize(lm + 1, 0);
			if (used[lm]) continue;
			pairs.emplace_back(i, lm);
			const double d = jointDistance(pairs);
			if (d <= gate(pairs.size()))
			{
				used[lm] = 1;
				current[i] = static_cast<int>(lm);
				search(i + 1, d);
				current[i] = -1;
				used[lm] = 0;
			}
			pairs.pop_back();
		}
		// Observation i unpaired (a new landmark, or spurious).
		search(i + 1, distance);
	};
	search(0, 0.0);
	return best;
}
}  // namespace featloc
