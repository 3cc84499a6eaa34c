#pragma once
#include <Eigen/Core>

namespace featloc
{
/** A reference plane fitted to disparity pixels (Moon, Miura & Shirai
 * 1999, eq. 11), and the plane constraint of section 3.1.
 *
 * The line is fitted in a frame of the camera's floor plan attached to
 * the plane's predicted position: origin at the predicted first end,
 * s along the plane (unit vector e), w across it (unit normal n). The
 * model w = a + b s is eq. (11), y = a + b x, in that frame; it stays
 * well conditioned for walls seen at a grazing angle (a corridor's side
 * walls), where y = a + b x in camera coordinates would not. */
struct PlaneFit
{
	Eigen::Vector2d origin = Eigen::Vector2d::Zero();  //!< camera coordinates [m]
	Eigen::Vector2d e = Eigen::Vector2d::UnitX(), n = Eigen::Vector2d::UnitY();
	Eigen::Vector2d line = Eigen::Vector2d::Zero();	 //!< (a [m], b)
	Eigen::Matrix2d lineCovariance = Eigen::Matrix2d::Zero();

	/** Plane frame (s, w) of camera point c, and back. */
	Eigen::Vector2d toPlane(const Eigen::Vector2d& c) const { return {e.dot(c - origin), n.dot(c - origin)}; }
	Eigen::Vector2d fromPlane(const Eigen::Vector2d& sw) const { return origin + sw.x() * e + sw.y() * n; }
	/** Unit direction of the fitted line in camera coordinates (towards +s). */
	Eigen::Vector2d direction() const { return (e + line.y() * n).normalized(); }

	/** Eqs. (12)-(14): a stereo point c~ with covariance P~ (camera
	 * coordinates) constrained to the fitted plane by one Kalman update,
	 * G(L, R) = w - (a + b s) = 0 with H = dG/dL and the line's own
	 * uncertainty as the observation noise, Sigma_V = dG/dR Sigma_R dG/dR^T.
	 * Returns the updated point and covariance (camera coordinates) and,
	 * in `mahalanobis2`, G(c~)^2 / (H P~ H^T + Sigma_V). `dLine`, if given,
	 * receives d(point)/d(a, b) at G = 0, as Pout has it (K [1 s] in the
	 * plane frame): every point constrained to this fit shares its line's
	 * error, Cov(c_i, c_j) = dLine_i lineCovariance dLine_j^T. */
	Eigen::Vector2d constrain(
		const Eigen::Vector2d& c, const Eigen::Matrix2d& P, Eigen::Matrix2d& Pout,
		double* mahalanobis2 = nullptr, Eigen::Matrix2d* dLine = nullptr) const;
};
}  // namespace featloc
