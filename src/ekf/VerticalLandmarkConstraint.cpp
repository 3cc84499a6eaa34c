#include "featloc/ekf/VerticalLandmarkConstraint.h"

#include <cmath>

namespace featloc
{
VerticalLandmarkConstraint::VerticalLandmarkConstraint(const VerticalLandmarkObservation& z) : m_z(z)
{
	m_rows = {0, 1};
	if (z.sigmaLow > 0) m_rows.push_back(2);
	if (z.sigmaHigh > 0) m_rows.push_back(3);
}

Eigen::VectorXd VerticalLandmarkConstraint::evaluate(
	const Eigen::Vector3d& X, const Eigen::Vector4d& l, Eigen::MatrixXd* GX, Eigen::MatrixXd* Gl) const
{
	const double c = std::cos(X.z()), s = std::sin(X.z());
	const Eigen::Vector2d d = l.head<2>() - X.head<2>();
	Eigen::Vector4d g;
	g << c * d.x() + s * d.y() - m_z.position.x(), -s * d.x() + c * d.y() - m_z.position.y(),
		l[2] - m_z.lLow, l[3] - m_z.lHigh;
	Eigen::Matrix<double, 4, 3> gx = Eigen::Matrix<double, 4, 3>::Zero();
	Eigen::Matrix4d gl = Eigen::Matrix4d::Identity();
	// d(R^T d)/d(x, y)_X = -R^T, d/dyaw = dR^T/dyaw d; d/d(x, y)_l = R^T.
	gx.block<2, 2>(0, 0) << -c, -s, s, -c;
	gx.block<2, 1>(0, 2) << -s * d.x() + c * d.y(), -c * d.x() - s * d.y();
	gl.block<2, 2>(0, 0) << c, s, -s, c;
	const Eigen::Index m = size();
	Eigen::VectorXd out(m);
	if (GX) GX->resize(m, 3);
	if (Gl) Gl->resize(m, 4);
	for (Eigen::Index r = 0; r < m; r++)
	{
		const int k = m_rows[static_cast<size_t>(r)];
		out[r] = g[k];
		if (GX) GX->row(r) = gx.row(k);
		if (Gl) Gl->row(r) = gl.row(k);
	}
	return out;
}

Eigen::MatrixXd VerticalLandmarkConstraint::noise() const
{
	Eigen::Matrix4d full = Eigen::Matrix4d::Zero();
	full.block<2, 2>(0, 0) = m_z.covariance;
	full(2, 2) = m_z.sigmaLow * m_z.sigmaLow;
	full(3, 3) = m_z.sigmaHigh * m_z.sigmaHigh;
	const Eigen::Index m = size();
	Eigen::MatrixXd R(m, m);
	for (Eigen::Index a = 0; a < m; a++)
		for (Eigen::Index b = 0; b < m; b++)
			R(a, b) = full(m_rows[static_cast<size_t>(a)], m_rows[static_cast<size_t>(b)]);
	return R;
}
}  // namespace featloc
