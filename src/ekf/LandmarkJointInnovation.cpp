#include "featloc/ekf/LandmarkJointInnovation.h"

#include <Eigen/Dense>
#include <array>
#include <limits>

#include "featloc/ekf/EkfLocalizer.h"

namespace featloc
{
namespace
{
std::array<Eigen::Index, 5> blockIndices(const EkfLocalizer& f, size_t landmark)
{
	const Eigen::Index k = f.landmarkIndex(landmark);
	return {EkfLocalizer::kRobot, EkfLocalizer::kRobot + 1, EkfLocalizer::kRobot + 2, k, k + 1};
}
}  // namespace

LandmarkJointInnovation::LandmarkJointInnovation(const EkfLocalizer& filter,
	const EkfLocalizer::Belief& belief, const std::vector<LandmarkObservation>& observations)
	: m_f(filter), m_b(belief), m_obs(observations)
{
}

double LandmarkJointInnovation::push(size_t i, size_t j)
{
	Pair pr;
	pr.landmark = j;
	Eigen::Matrix<double, 2, 3> Hr;
	Eigen::Matrix2d Hl;
	pr.nu = m_obs[i].position - m_f.predictObservation(m_b.x, j, &Hr, &Hl);
	pr.H << Hr, Hl;
	const auto& P = m_b.P;
	const auto idx = blockIndices(m_f, j);
	const Eigen::Matrix2d c = pr.H * P(idx, idx) * pr.H.transpose() + m_obs[i].covariance;

	const Eigen::Index m = 2 * static_cast<Eigen::Index>(m_pairs.size());
	double d2 = std::numeric_limits<double>::infinity();
	Eigen::MatrixXd inverse(m + 2, m + 2);
	if (m == 0)
	{
		const Eigen::Matrix2d ci = c.inverse();
		inverse = ci;
		d2 = pr.nu.dot(ci * pr.nu);
	}
	else
	{
		// Cross-covariance of the new innovation with each earlier one:
		// they share the robot (and the landmark, when the same).
		Eigen::MatrixXd b(m, 2);
		for (size_t a = 0; a < m_pairs.size(); a++)
			b.block<2, 2>(2 * static_cast<Eigen::Index>(a), 0) =
				m_pairs[a].H * P(blockIndices(m_f, m_pairs[a].landmark), idx) * pr.H.transpose();
		const Eigen::MatrixXd& Ainv = m_inverse.back();
		const Eigen::MatrixXd w = Ainv * b;	 // m x 2
		const Eigen::Matrix2d schur = c - b.transpose() * w;
		const Eigen::Matrix2d si = schur.inverse();
		const Eigen::Vector2d e = pr.nu - w.transpose() * m_nu;
		if (schur.determinant() > 0 && schur(0, 0) > 0) d2 = m_d2.back() + e.dot(si * e);
		inverse.topLeftCorner(m, m) = Ainv + w * si * w.transpose();
		inverse.topRightCorner(m, 2) = -w * si;
		inverse.bottomLeftCorner(2, m) = -si * w.transpose();
		inverse.bottomRightCorner<2, 2>() = si;
	}
	m_pairs.push_back(pr);
	m_d2.push_back(d2);
	m_inverse.push_back(std::move(inverse));
	m_nu.conservativeResize(m + 2);
	m_nu.tail<2>() = pr.nu;
	return d2;
}

void LandmarkJointInnovation::pop()
{
	m_pairs.pop_back();
	m_d2.pop_back();
	m_inverse.pop_back();
	m_nu.conservativeResize(m_nu.size() - 2);
}
}  // namespace featloc
