#include "featloc/stereo/StereoWallObservation.h"

#include <cmath>

namespace featloc
{
Eigen::Vector2d StereoWallObservation::predict(const Eigen::Vector3d& X, Eigen::Matrix<double, 2, 3>* H) const
{
	const double c = std::cos(X.z()), s = std::sin(X.z());
	Eigen::Matrix2d M;	// world -> plane frame, through the robot frame
	M.row(0) = e.transpose();
	M.row(1) = n.transpose();
	// p_r = R^T (p - t); dp_r/dt = -R^T, dp_r/dyaw = (p_r.y, -p_r.x).
	Eigen::Matrix2d Rt;
	Rt << c, s, -s, c;
	auto end = [&](const Eigen::Vector2d& p, Eigen::Matrix<double, 2, 3>& J) {
		const Eigen::Vector2d pr = Rt * (p - X.head<2>());
		J.block<2, 2>(0, 0) = -M * Rt;
		J.col(2) = M * Eigen::Vector2d(pr.y(), -pr.x());
		return Eigen::Vector2d(M * (pr - origin));	// (s, w)
	};
	Eigen::Matrix<double, 2, 3> Ja, Jb;
	const Eigen::Vector2d pa = end(mapA, Ja), pb = end(mapB, Jb);
	// The line through them: b = (w_b - w_a) / (s_b - s_a), a = w_a - b s_a.
	const double ds = pb.x() - pa.x(), dw = pb.y() - pa.y();
	const double slope = dw / ds, a = pa.y() - slope * pa.x();
	if (H)
	{
		const Eigen::RowVector3d dSlope =
			(Jb.row(1) - Ja.row(1)) / ds - dw * (Jb.row(0) - Ja.row(0)) / (ds * ds);
		H->row(1) = dSlope;
		H->row(0) = Ja.row(1) - slope * Ja.row(0) - pa.x() * dSlope;
	}
	return {a, slope};
}
}  // namespace featloc
