#include "featloc/stereo/PlaneFit.h"

#include <Eigen/Dense>

namespace featloc
{
Eigen::Vector2d PlaneFit::constrain(
	const Eigen::Vector2d& c, const Eigen::Matrix2d& P, Eigen::Matrix2d& Pout, double* mahalanobis2,
	Eigen::Matrix2d* dLine) const
{
	// To the plane frame: L = (s, w) = R^T (c - o), R = [e n].
	Eigen::Matrix2d R;
	R.col(0) = e;
	R.col(1) = n;
	const Eigen::Vector2d L = toPlane(c);
	const Eigen::Matrix2d PL = R.transpose() * P * R;
	const double a = line.x(), b = line.y();
	// Eq. (12): G = w - (a + b s); eq. (13): H = dG/dL = [-b 1];
	// eq. (14): Sigma_V = dG/dR Sigma_R dG/dR^T with dG/dR = -[1 s].
	const Eigen::RowVector2d H(-b, 1.0);
	const Eigen::RowVector2d dGdR(-1.0, -L.x());
	const double G = L.y() - (a + b * L.x());
	const double SV = dGdR * lineCovariance * dGdR.transpose();
	const double S = H * PL * H.transpose() + SV;
	const Eigen::Vector2d K = PL * H.transpose() / S;
	// The Kalman update of section 3.1 with Y - H L~ = -G(L~, R~).
	const Eigen::Vector2d Lhat = L - K * G;
	Eigen::Matrix2d PLhat = (Eigen::Matrix2d::Identity() - K * H) * PL;
	PLhat = 0.5 * (PLhat + PLhat.transpose()).eval();
	if (mahalanobis2) *mahalanobis2 = G * G / S;
	Pout = R * PLhat * R.transpose();
	// L^ = L - K G, dG/dR = -[1 s]: dL^/dR = K [1 s], the line error's
	// share in Pout (K Sigma_V K^T). (K also depends on b; that term is
	// proportional to G and is left out of Pout too.)
	if (dLine) *dLine = R * K * Eigen::RowVector2d(1.0, L.x());
	return fromPlane(Lhat);
}
}  // namespace featloc
