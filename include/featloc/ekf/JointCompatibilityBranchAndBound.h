#pragma once
#include <cstddef>
#include <functional>
#include <vector>

namespace featloc
{
/** Neira & Tardos' Joint Compatibility Branch and Bound (IEEE Trans.
 * Robotics and Automation 17(6), 2001): among all ways to pair observations
 * with landmarks, each observation with at most one individually compatible
 * landmark and no landmark twice, the one with the most pairings whose
 * innovations are jointly compatible (their stacked Mahalanobis distance
 * under the joint innovation covariance within the chi-square gate of their
 * dimension); ties go to the smaller joint distance. Pairings share the
 * robot's uncertainty, so near-identical landmarks that are each compatible
 * with an observation are told apart by what the other observations say.
 *
 * The filter supplies the geometry through a JointInnovation: the
 * hypothesis grows and shrinks by one pair at a time, so the joint distance
 * is updated incrementally (O(k^2) per pair for k pairs) rather than
 * recomputed. Pairs already in it when solve() starts (known identities)
 * are the base every hypothesis extends. Depth-first over the observations,
 * a branch is cut when even pairing every remaining observation could not
 * beat the best hypothesis; after 200000 hypotheses (a pathological scene)
 * the best one found stands. */
class JointCompatibilityBranchAndBound
{
   public:
	using Pairing = std::vector<int>;  //!< per observation: landmark index or -1

	/** The joint innovation of the current hypothesis. */
	class JointInnovation
	{
	   public:
		virtual ~JointInnovation() = default;
		/** Adds a pair; returns the joint squared Mahalanobis distance of
		 * every pair now in the hypothesis. */
		virtual double push(size_t observation, size_t landmark) = 0;
		/** Removes the pair added last. */
		virtual void pop() = 0;
		/** Pairs in the hypothesis. */
		virtual size_t size() const = 0;
		/** Joint squared distance of the pairs in the hypothesis. */
		virtual double distance() const = 0;
	};

	/** Chi-square threshold for a hypothesis of k pairs. */
	using Gate = std::function<double(size_t pairs)>;

	/** `candidates[i]`: the landmarks individually compatible with
	 * observation i. `joint` may hold base pairs already (never removed). */
	static Pairing solve(
		const std::vector<std::vector<size_t>>& candidates, JointInnovation& joint,
		const Gate& gate);

	/** Same with a joint distance recomputed from scratch for each
	 * hypothesis (for tests and small problems). */
	using JointDistance = std::function<double(const std::vector<std::pair<size_t, size_t>>&)>;
	static Pairing solve(
		const std::vector<std::vector<size_t>>& candidates, const JointDistance& jointDistance,
		const Gate& gate);
};
}  // namespace featloc
