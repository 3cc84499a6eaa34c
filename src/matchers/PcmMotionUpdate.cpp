#include "featloc/matchers/PcmMotionUpdate.h"

#include <mrpt/math/wrap2pi.h>

#include <Eigen/Dense>
#include <cmath>
#include <limits>

#include "featloc/math/PolynomialRoots.h"

namespace featloc
{
void PcmMotionUpdate::predict(
	const ScanFeature& f, const mrpt::math::TPose2D& m, double& x, double& y)
{
	predict(f, m, std::cos(m.phi), std::sin(m.phi), x, y);
}

void PcmMotionUpdate::predict(const ScanFeature& f, const mrpt::math::TPose2D& m, double cw,
	double sw, double& x, double& y)
{
	// f_i - A_i t, then R(w) = [cos sin; -sin cos] (eq. 2).
	const double px = f.x - (f.a2 * m.x + f.c * m.y);
	const double py = f.y - (f.c * m.x + f.b2 * m.y);
	x = cw * px + sw * py;
	y = -sw * px + cw * py;
}

double PcmMotionUpdate::cost(
	const std::vector<ScanFeature>& reference,
	const std::vector<ScanFeature>& current,
	const std::vector<FeaturePair>& pairs, const mrpt::math::TPose2D& motion)
{
	double e = 0;
	const double cw = std::cos(motion.phi), sw = std::sin(motion.phi);
	for (const auto& p : pairs)
	{
		double lx = 0, ly = 0;
		predict(reference[p.i], motion, cw, sw, lx, ly);
		const double dx = current[p.j].x - lx, dy = current[p.j].y - ly;
		e += p.mu * (dx * dx + dy * dy);
	}
	return e;
}

mrpt::math::TPose2D PcmMotionUpdate::solve(
	const std::vector<ScanFeature>& reference,
	const std::vector<ScanFeature>& current,
	const std::vector<FeaturePair>& pairs, const mrpt::math::TPose2D& previous,
	double damping, double windowCentre, double windowHalfWidth)
{
	Eigen::Matrix2d M = Eigen::Matrix2d::Zero(), N = Eigen::Matrix2d::Zero();
	Eigen::Vector2d q = Eigen::Vector2d::Zero(), r = Eigen::Vector2d::Zero();
	for (const auto& p : pairs)
	{
		const ScanFeature& fi = reference[p.i];
		const ScanFeature& fj = current[p.j];
		Eigen::Matrix2d A;
		A << fi.a2, fi.c, fi.c, fi.b2;
		Eigen::Matrix2d F;	// R(w)^T f_j = F beta
		F << fj.x, -fj.y, fj.y, fj.x;
		M += p.mu * A;	// eq. (18): A^T A = A
		N -= p.mu * A * F;	// eq. (19)
		q += p.mu * A * Eigen::Vector2d(fi.x, fi.y);  // eq. (20)
		r += p.mu * Eigen::Vector2d(fi.y * fj.x - fi.x * fj.y,	// eq. (21)
						-fi.x * fj.x - fi.y * fj.y);
	}
	const double kappa = damping * (1 + M.trace());
	M += kappa * Eigen::Matrix2d::Identity();
	q += kappa * Eigen::Vector2d(previous.x, previous.y);

	Eigen::Matrix2d P;	// eq. (22)
	P << 0, 1, -1, 0;
	P = P * N.transpose();
	const Eigen::Matrix2d Minv = M.inverse();
	const Eigen::Matrix2d Q = P * Minv * N;
	const Eigen::Vector2d s = r + P * Minv * q;	 // eq. (23), with q

	// U(z) + cos(w) V(z) = 0 squared: U^2 - (1 - z^2) V^2 = 0.
	const double D = Q(1, 1) - Q(0, 0), K = Q(0, 1) + Q(1, 0);
	const double q00 = Q(0, 0), s0 = s[0], s1 = s[1];
	const std::vector<double> quartic = {
		q00 * q00 - s0 * s0,
		2 * q00 * s1 - 2 * s0 * K,
		s1 * s1 + 2 * q00 * D - K * K + s0 * s0,
		2 * s1 * D + 2 * s0 * K,
		D * D + K * K};

	auto motionFor = [&](double w) {
		const Eigen::Vector2d t = Minv * (N * Eigen::Vector2d(std::cos(w), std::sin(w)) + q);
		return mrpt::math::TPose2D(t[0], t[1], mrpt::math::wrapToPi(w));
	};
	auto energy = [&](const mrpt::math::TPose2D& m) {
		return cost(reference, current, pairs, m) +
			kappa * ((m.x - previous.x) * (m.x - previous.x) +
					 (m.y - previous.y) * (m.y - previous.y));
	};
	// The previous rotation is a candidate too: with no rotation
	// information (identically zero quartic) it is kept.
	mrpt::math::TPose2D best = motionFor(previous.phi);
	double bestE = energy(best);
	for (double z : PolynomialRoots::real(quartic))
	{
		if (z < -1 - 1e-9 || z > 1 + 1e-9) continue;
		const double w = std::asin(std::clamp(z, -1.0, 1.0));
		for (double cand : {w, M_PI - w})
		{
			if (windowHalfWidth > 0 &&
				std::abs(mrpt::math::wrapToPi(cand - windowCentre)) > windowHalfWidth)
				continue;
			const auto m = motionFor(cand);
			const double e = energy(m);
			if (e < bestE)
			{
				bestE = e;
				best = m;
			}
		}
	}
	return best;
}
}  // namespace featloc
