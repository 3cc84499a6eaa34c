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

/** A JointInnovation over a from-scratch distance function. */
class RecomputedJointInnovation : public JointCompatibilityBranchAndBound::JointInnovation
{
   public:
	explicit RecomputedJointInnovation(const JointCompatibilityBranchAndBound::JointDistance& f)
		: m_f(f)
	{
	}
	double push(size_t i, size_t j) override
	{
		m_pairs.emplace_back(i, j);
		m_d.push_back(m_f(m_pairs));
		return m_d.back();
	}
	void pop() override
	{
		m_pairs.pop_back();
		m_d.pop_back();
	}
	size_t size() const override { return m_pairs.size(); }
	double distance() const override { return m_d.empty() ? 0.0 : m_d.back(); }

   private:
	const JointCompatibilityBranchAndBound::JointDistance& m_f;
	std::vector<std::pair<size_t, size_t>> m_pairs;
	std::vector<double> m_d;
};
}  // namespace

JointCompatibilityBranchAndBound::Pairing JointCompatibilityBranchAndBound::solve(
	const std::vector<std::vector<size_t>>& candidates, const JointDistance& jointDistance,
	const Gate& gate)
{
	RecomputedJointInnovation joint(jointDistance);
	return solve(candidates, joint, gate);
}

JointCompatibilityBranchAndBound::Pairing JointCompatibilityBranchAndBound::solve(
	const std::vector<std::vector<size_t>>& candidates, JointInnovation& joint, const Gate& gate)
{
	const size_t n = candidates.size();
	const size_t base = joint.size();
	Pairing best(n, -1), current(n, -1);
	size_t bestPairs = 0;
	double bestDistance = std::numeric_limits<double>::infinity();
	std::vector<char> used;

	// Observations that can still pair, from i on (for the bound).
	std::vector<size_t> pairableFrom(n + 1, 0);
	for (size_t i = n; i-- > 0;)
		pairableFrom[i] = pairableFrom[i + 1] + (candidates[i].empty() ? 0 : 1);

	size_t nodes = 0;
	std::function<void(size_t)> search = [&](size_t i) {
		const size_t paired = joint.size() - base;
		if (paired + pairableFrom[i] < bestPairs) return;  // cannot win
		if (++nodes > kMaxNodes) return;  // the best found so far stands
		if (i == n)
		{
			const double distance = joint.distance();
			if (paired > bestPairs || (paired == bestPairs && distance < bestDistance))
			{
				best = current;
				bestPairs = paired;
				bestDistance = distance;
			}
			return;
		}
		for (size_t lm : candidates[i])
		{
			if (lm >= used.size()) used.resize(lm + 1, 0);
			if (used[lm]) continue;
			const double d = joint.push(i, lm);
			if (d <= gate(joint.size()))
			{
				used[lm] = 1;
				current[i] = static_cast<int>(lm);
				search(i + 1);
				current[i] = -1;
				used[lm] = 0;
			}
			joint.pop();
		}
		// Observation i unpaired (a new landmark, or spurious).
		search(i + 1);
	};
	search(0);
	return best;
}
}  // namespace featloc
