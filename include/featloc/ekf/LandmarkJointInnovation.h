#pragma once
#include <Eigen/Core>
#include <vector>

#include "featloc/ekf/EkfLocalizer.h"
#include "featloc/ekf/JointCompatibilityBranchAndBound.h"
#include "featloc/ekf/LandmarkObservation.h"

namespace featloc
{
/** The joint innovation of (observation, landmark) pairs against an
 * EkfLocalizer's belief (its state with the held match applied), grown and shrunk one pair at a time for JCBB.
 *
 * Each pair's Jacobian touches the robot (3) and its landmark (2) only, so
 * the new rows of the joint covariance S cost O(k) small blocks, and the
 * joint distance nu^T S^-1 nu is extended by the Schur complement of the
 * new pair: with S = [A b; b^T c] and nu = [u; v], w = A^-1 b,
 * d2' = d2 + (v - w^T u)^T (c - b^T w)^-1 (v - w^T u), and A^-1 is
 * extended by the block-inverse formula. O(k^2) per push instead of
 * O(k^3) (and O(k n^2) for a dense H P H^T). */
class LandmarkJointInnovation : public JointCompatibilityBranchAndBound::JointInnovation
{
   public:
	LandmarkJointInnovation(const EkfLocalizer& filter, const EkfLocalizer::Belief& belief,
		const std::vector<LandmarkObservation>& observations);

	double push(size_t observation, size_t landmark) override;
	void pop() override;
	size_t size() const override { return m_pairs.size(); }
	double distance() const override { return m_d2.empty() ? 0.0 : m_d2.back(); }

   private:
	struct Pair
	{
		size_t landmark;
		Eigen::Matrix<double, 2, 5> H;	//!< on [robot; landmark]
		Eigen::Vector2d nu;
	};
	const EkfLocalizer& m_f;
	const EkfLocalizer::Belief& m_b;
	const std::vector<LandmarkObservation>& m_obs;
	std::vector<Pair> m_pairs;
	std::vector<double> m_d2;
	std::vector<Eigen::MatrixXd> m_inverse;	 //!< S^-1 of the first k pairs, per k
	Eigen::VectorXd m_nu;  //!< stacked innovations
};
}  // namespace featloc
