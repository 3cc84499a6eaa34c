#include "featloc/features/CircleFit.h"

#include <Eigen/Dense>
#include <cmath>

namespace featloc
{
bool CircleFit::fit(const ScanPoint* p, size_t count, double maxRadius, CircleFit& out)
{
	out = CircleFit();
	out.n = count;
	if (count < 3) return false;
	// Kasa about the centroid (conditioning far from the origin): minimise
	// sum (u^2 + v^2 + D u + E v + F)^2, u, v the centred coordinates.
	double mx = 0, my = 0;
	for (size_t j = 0; j < count; j++)
	{
		mx += p[j].x;
		my += p[j].y;
	}
	mx /= static_cast<double>(count);
	my /= static_cast<double>(count);
	Eigen::Matrix3d M = Eigen::Matrix3d::Zero();
	Eigen::Vector3d b = Eigen::Vector3d::Zero();
	for (size_t j = 0; j < count; j++)
	{
		const double u = p[j].x - mx, v = p[j].y - my;
		const Eigen::Vector3d row(u, v, 1);
		M += row * row.transpose();
		b -= row * (u * u + v * v);
	}
	const Eigen::Vector3d def = M.ldlt().solve(b);
	if (!def.allFinite()) return false;
	double ox = -def[0] / 2, oy = -def[1] / 2;
	const double r2 = ox * ox + oy * oy - def[2];
	if (!(r2 > 0)) return false;
	double r = std::sqrt(r2);
	if (!(r <= 4 * maxRadius)) return false;
	// Gauss-Newton on the geometric distances; Kasa's start is close on
	// an arc of a few degrees' noise, a few steps converge.
	Eigen::Matrix3d AtA;
	for (int it = 0; it < 20; it++)
	{
		AtA.setZero();
		Eigen::Vector3d Atf = Eigen::Vector3d::Zero();
		for (size_t j = 0; j < count; j++)
		{
			const double dx = p[j].x - mx - ox, dy = p[j].y - my - oy;
			const double d = std::hypot(dx, dy);
			if (!(d > 0)) return false;
			const Eigen::Vector3d a(-dx / d, -dy / d, -1);
			AtA += a * a.transpose();
			Atf += a * (d - r);
		}
		const Eigen::Vector3d step = -AtA.ldlt().solve(Atf);
		if (!step.allFinite()) return false;
		ox += step[0];
		oy += step[1];
		r += step[2];
		if (step.squaredNorm() < 1e-20) break;
	}
	if (!(r > 0 && r <= maxRadius)) return false;
	AtA.setZero();
	double ss = 0;
	for (size_t j = 0; j < count; j++)
	{
		const double dx = p[j].x - mx - ox, dy = p[j].y - my - oy;
		const double d = std::hypot(dx, dy);
		const Eigen::Vector3d a(-dx / d, -dy / d, -1);
		AtA += a * a.transpose();
		ss += (d - r) * (d - r);
	}
	const Eigen::FullPivLU<Eigen::Matrix3d> lu(AtA);
	if (!lu.isInvertible()) return false;
	out.ox = ox + mx;
	out.oy = oy + my;
	out.r = r;
	out.sumSquares = ss;
	out.normalInverse = lu.inverse();
	return out.normalInverse.allFinite();
}

double CircleFit::centreVariance(double tx, double ty, double s) const
{
	const Eigen::Vector2d t(tx, ty);
	return s * s * t.dot(normalInverse.topLeftCorner<2, 2>() * t);
}
}  // namespace featloc
