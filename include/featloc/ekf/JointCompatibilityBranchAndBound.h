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
 * The filter supplies the geometry through `jointDistance`: the squared
 * Mahalanobis distance of a set of (observation, landmark) pairs, and
 * `gate(k)`: the chi-square threshold for k pairs. Depth-first over the
 * observations, a branch is cut when even pairing every remaining
 * observation could not beat the best hypothesis; after 200000 hypotheses
 * (a pathological scene) the best one found stands. */
class JointCompatibilityBranchAndBound
{
   public:
	using Pairing = std::vector<int>;  //!< per observation: landmark index or -1
	using JointDistance = std::function<double(const std::vector<std::pair<size_t, size_t>>&)>;
	using Gate = std::function<double(size_t pairs)>;

	/** `candidates[i]`: the landmarks individually compatible with
	 * observation i. */
	static Pairing solve(
		const std::vector<std::vector<size_t>>& candidates, const JointDistance& jointDistance,
		const Gate& gate);
};
}  // namespace featloc
