#pragma once
#include <Eigen/Core>

#include <vector>

#include "featloc/stereo/VerticalLandmarkObservation.h"

namespace featloc
{
/** The observation constraint of Moon, Miura & Shirai's eq. (20),
 * G(S_t, L_t) = 0, for a vertical-line landmark l = [x y l_low l_high]
 * (world frame) seen from the robot pose X = (x, y, yaw) as the
 * observation L = (position p in the robot frame, heights of the ends):
 *
 *     G = [ R(yaw)^T ((x, y)_l - (x, y)_X) - p ;
 *           l_low  - L.lLow  ;
 *           l_high - L.lHigh ]
 *
 * with an end's row left out where that end is not observed. The EKF
 * update of the implicit form (as in section 3.1) is nu = -G(S, L),
 * H = dG/dS, R = dG/dL Sigma_L dG/dL^T, and dG/dL = -I. */
class VerticalLandmarkConstraint
{
   public:
	explicit VerticalLandmarkConstraint(const VerticalLandmarkObservation& z);

	/** Rows of G that the observation has: 0, 1 (position), then 2 (low
	 * end) and 3 (high end) where observed. */
	const std::vector<int>& rows() const { return m_rows; }
	Eigen::Index size() const { return static_cast<Eigen::Index>(m_rows.size()); }

	/** G at robot X and landmark l (the observed rows), and optionally
	 * dG/dX (rows x 3) and dG/dl (rows x 4). */
	Eigen::VectorXd evaluate(
		const Eigen::Vector3d& X, const Eigen::Vector4d& l, Eigen::MatrixXd* GX = nullptr,
		Eigen::MatrixXd* Gl = nullptr) const;
	/** dG/dL Sigma_L dG/dL^T over the observed rows. */
	Eigen::MatrixXd noise() const;

   private:
	VerticalLandmarkObservation m_z;
	std::vector<int> m_rows;
};
}  // namespace featloc
