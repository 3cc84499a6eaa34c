#include "featloc/matchers/PointToLineCovariance.h"

#include <mrpt/core/bits_math.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <tuple>
#include <vector>

namespace featloc
{
double PointToLineCovariance::residual(
	const mrpt::math::TPose2D& x, double c, double s, const ScanPoint& p,
	const ReferencePolyline::LocalLine& L, Eigen::Vector3d* gradient)
{
	const double qx = c * p.x - s * p.y + x.x, qy = s * p.x + c * p.y + x.y;
	// The offset from the line less the surface's parabola there
	// (LocalLine::tilt and bow, 0 on straight lines): e = n.d - c (t.d) - b
	// ((t.d)^2 - mean s^2), d = q - centroid, t = (ny, -nx); de/dq = n -
	// (c + 2 b (t.d)) t.
	const double dx = qx - L.cx, dy = qy - L.cy;
	const double along = L.ny * dx - L.nx * dy;
	if (gradient)
	{
		const double k = L.tilt + 2 * L.bow * along;
		const double nx = L.nx - k * L.ny, ny = L.ny + k * L.nx;
		// d(R p)/dw = (-s px - c py, c px - s py)
		(*gradient)[0] = nx;
		(*gradient)[1] = ny;
		(*gradient)[2] = nx * (-s * p.x - c * p.y) + ny * (c * p.x - s * p.y);
	}
	return L.nx * dx + L.ny * dy - L.tilt * along - L.bow * (along * along - L.meanAlong2);
}

double PointToLineCovariance::residual(
	const mrpt::math::TPose2D& x, double c, double s, const ScanPoint& p,
	const ReferencePolyline::RoundThing& thing, Eigen::Vector3d* gradient)
{
	// e = |q - o| - r, de/dq = the radial unit n.
	const double qx = c * p.x - s * p.y + x.x, qy = s * p.x + c * p.y + x.y;
	const double dx = qx - thing.circle.ox, dy = qy - thing.circle.oy;
	const double d = std::max(std::hypot(dx, dy), 1e-12);
	if (gradient)
	{
		const double nx = dx / d, ny = dy / d;
		(*gradient)[0] = nx;
		(*gradient)[1] = ny;
		(*gradient)[2] = nx * (-s * p.x - c * p.y) + ny * (c * p.x - s * p.y);
	}
	return d - thing.circle.r;
}

double PointToLineCovariance::residual(const mrpt::math::TPose2D& x, double c, double s,
	const std::vector<ScanPoint>& current, const ReferencePolyline& reference,
	const PointToLinePair& pair, Eigen::Vector3d* gradient)
{
	const ScanPoint& p = current[pair.current];
	return pair.round >= 0 ? residual(x, c, s, p, reference.roundThing(pair.round), gradient)
						   : residual(x, c, s, p, reference.localLine(pair.a), gradient);
}

void PointToLineCovariance::rangeDerivatives(
	const mrpt::math::TPose2D& x, const ScanPoint& p, const ReferencePolyline::LocalLine& L,
	const ReferencePolyline& reference, std::vector<double>& dedz,
	Eigen::Matrix<double, 3, Eigen::Dynamic>* mixed)
{
	const double ca = L.ny, sa = -L.nx;	 // the direction t = (ca, sa)
	const double nx = L.nx, ny = L.ny;
	const double c = std::cos(x.phi), s = std::sin(x.phi);
	const double qx = c * p.x - s * p.y + x.x, qy = s * p.x + c * p.y + x.y;
	// R' p (d(R p)/dw) and R u_p, R' u_p for the current point's beam.
	const double ux = p.x / p.range, uy = p.y / p.range;  // the beam
	const double rpx = -s * p.x - c * p.y, rpy = c * p.x - s * p.y;
	const size_t m = L.hi - L.lo + 1;
	dedz.assign(1 + m, 0.0);
	if (mixed) mixed->setZero(3, static_cast<Eigen::Index>(1 + m));
	// Current point: it moves along its beam, R u, with de/dq = g = n - (c +
	// 2 b (t.d)) t on a bowed line (residual()); de/dx = (g, g.R'p) changes
	// by -2 b (t.Ru) t and by its effect on g.R'p, plus g.R'u. The
	// parabola's own dependence on the reference ranges is left out (its
	// points' effect through the centroid and direction below is the
	// line's).
	const double along = ca * (qx - L.cx) + sa * (qy - L.cy);
	const double k = L.tilt + 2 * L.bow * along;
	const double gx = nx - k * ca, gy = ny - k * sa;
	const double rux = c * ux - s * uy, ruy = s * ux + c * uy;
	dedz[0] = gx * rux + gy * ruy;
	if (mixed)
	{
		const double dg = -2 * L.bow * (ca * rux + sa * ruy);
		(*mixed)(0, 0) = dg * ca;
		(*mixed)(1, 0) = dg * sa;
		(*mixed)(2, 0) = dg * (ca * rpx + sa * rpy) + gx * (-s * ux - c * uy) + gy * (c * ux - s * uy);
	}
	// Reference points: through the centroid and the direction.
	const double dedAlpha = -along;
	const double c2 = ca * ca - sa * sa, s2 = 2 * sa * ca;	// of 2 alpha
	const Eigen::Vector3d dGradDAlpha(-ca, -sa, -(ca * rpx + sa * rpy));
	for (size_t k = 0; k < m; k++)
	{
		const ScanPoint& pj = reference.point(static_cast<uint32_t>(L.lo + k));
		const double dx = pj.x - L.cx, dy = pj.y - L.cy;
		const double daX = (c2 * dy - s2 * dx) / L.gap, daY = (c2 * dx + s2 * dy) / L.gap;
		const double ujx = pj.x / pj.range, ujy = pj.y / pj.range;
		const double dAlpha = daX * ujx + daY * ujy;
		dedz[1 + k] = -(nx * ujx + ny * ujy) / static_cast<double>(m) + dedAlpha * dAlpha;
		if (mixed) mixed->col(static_cast<Eigen::Index>(1 + k)) = dGradDAlpha * dAlpha;
	}
}

void PointToLineCovariance::rangeDerivatives(const mrpt::math::TPose2D& x, const ScanPoint& p,
	const ReferencePolyline::RoundThing& thing, const ReferencePolyline& reference,
	std::vector<double>& dedz, Eigen::Matrix<double, 3, Eigen::Dynamic>* mixed)
{
	const CircleFit& circle = thing.circle;
	const double c = std::cos(x.phi), s = std::sin(x.phi);
	const double qx = c * p.x - s * p.y + x.x, qy = s * p.x + c * p.y + x.y;
	const double ux = p.x / p.range, uy = p.y / p.range;  // the beam
	const double rpx = -s * p.x - c * p.y, rpy = c * p.x - s * p.y;	 // d(R p)/dw
	const double rux = c * ux - s * uy, ruy = s * ux + c * uy;	// R u
	const double dx = qx - circle.ox, dy = qy - circle.oy;
	const double d = std::max(std::hypot(dx, dy), 1e-12);
	const double nx = dx / d, ny = dy / d;
	// The radial unit turns by P v / d for a move v of q (or -v of the
	// centre), P = I - n n^T; de/dx = (n, n.R'p).
	auto turn = [&](double vx, double vy, double& tx, double& ty) {
		const double along = nx * vx + ny * vy;
		tx = (vx - along * nx) / d;
		ty = (vy - along * ny) / d;
	};
	const size_t m = thing.hi - thing.lo + 1;
	dedz.assign(1 + m, 0.0);
	if (mixed) mixed->setZero(3, static_cast<Eigen::Index>(1 + m));
	// Current point: it moves along its beam R u.
	dedz[0] = nx * rux + ny * ruy;
	if (mixed)
	{
		double tx, ty;
		turn(rux, ruy, tx, ty);
		(*mixed)(0, 0) = tx;
		(*mixed)(1, 0) = ty;
		(*mixed)(2, 0) = tx * rpx + ty * rpy + nx * (-s * ux - c * uy) + ny * (c * ux - s * uy);
	}
	// Reference points: through the circle's centre and radius, theta = (ox,
	// oy, r), whose least squares make sum_j a_j f_j = 0 with a_j =
	// df_j/dtheta = (-n_j, -1): d theta/dz_j = -(A^T A)^-1 a_j (n_j.u_j) to
	// first order (CircleFit), and de/dtheta = (-n, -1).
	const Eigen::Vector3d aq(-nx, -ny, -1);
	for (size_t k = 0; k < m; k++)
	{
		const ScanPoint& pj = reference.point(static_cast<uint32_t>(thing.lo + k));
		const double djx = pj.x - circle.ox, djy = pj.y - circle.oy;
		const double dj = std::max(std::hypot(djx, djy), 1e-12);
		const Eigen::Vector3d aj(-djx / dj, -djy / dj, -1);
		const double radial = (djx * pj.x + djy * pj.y) / (dj * pj.range);
		const Eigen::Vector3d dTheta = -circle.normalInverse * aj * radial;
		dedz[1 + k] = aq.dot(dTheta);
		if (mixed)
		{
			double tx, ty;
			turn(-dTheta[0], -dTheta[1], tx, ty);
			(*mixed)(0, static_cast<Eigen::Index>(1 + k)) = tx;
			(*mixed)(1, static_cast<Eigen::Index>(1 + k)) = ty;
			(*mixed)(2, static_cast<Eigen::Index>(1 + k)) = tx * rpx + ty * rpy;
		}
	}
}

double PointToLineCovariance::normalVariance(const mrpt::math::TPose2D& x, double c, double s,
	const std::vector<ScanPoint>& current, const ReferencePolyline& reference,
	const PointToLinePair& pair)
{
	if (pair.round < 0) return mrpt::square(reference.directionSigma(pair.a));
	const ScanPoint& p = current[pair.current];
	return reference.roundNormalVariance(
		pair.round, c * p.x - s * p.y + x.x, s * p.x + c * p.y + x.y);
}

Eigen::Vector3d PointToLineCovariance::surfaceDirection(double c, double s, const ScanPoint& p,
	const ReferencePolyline& reference, const PointToLinePair& pair, const Eigen::Vector3d& gradient)
{
	const ReferencePolyline::LocalLine& L = reference.localLine(pair.a);
	const bool round = pair.round >= 0;
	const double tx = round ? -gradient[1] : L.ny, ty = round ? gradient[0] : -L.nx;
	const double rx = c * p.x - s * p.y, ry = s * p.x + c * p.y;  // R p; R'p = (-ry, rx)
	return {tx, ty, -tx * ry + ty * rx};
}

Eigen::Matrix3d PointToLineCovariance::inventedInformation(const mrpt::math::TPose2D& x, double c,
	double s, const std::vector<ScanPoint>& current, const ReferencePolyline& reference,
	const PointToLinePair& pair, const Eigen::Vector3d& gradient)
{
	const Eigen::Vector3d dt = surfaceDirection(c, s, current[pair.current], reference, pair, gradient);
	return normalVariance(x, c, s, current, reference, pair) * dt * dt.transpose();
}

bool PointToLineCovariance::fixesEveryDirection(
	const Eigen::Matrix3d& information, const Eigen::Matrix3d& invented)
{
	const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(information);
	const Eigen::Vector3d weakest = eig.eigenvectors().col(0);
	return eig.eigenvalues()[0] > kInventedMargin * weakest.dot(invented * weakest);
}

bool PointToLineCovariance::compute(
	const std::vector<ScanPoint>& current, const ReferencePolyline& reference,
	const std::vector<PointToLinePair>& pairs, const mrpt::math::TPose2D& x,
	double minSigma, double latticeCellSigma, Eigen::Matrix3d& cov, double& sigma,
	Eigen::Matrix3d& information, double residualSpan)
{
	const size_t nc = current.size();
	// g_k for every range z_k: current points first, then reference points.
	std::vector<Eigen::Vector3d> g(nc + reference.size(), Eigen::Vector3d::Zero());
	Eigen::Matrix3d H = Eigen::Matrix3d::Zero();
	// The information the local lines' direction errors add on average.
	Eigen::Matrix3d invented = Eigen::Matrix3d::Zero();
	double J = 0, sensitivity = 0;
	std::vector<double> dedz;
	Eigen::Matrix<double, 3, Eigen::Dynamic> mixed;
	// Each pair's score u_i = d(e_i^2)/dx (residualSpan), kept per thread.
	thread_local std::vector<std::pair<uint32_t, Eigen::Vector3d>> scores;
	scores.clear();
	const double c = std::cos(x.phi), s = std::sin(x.phi);
	for (const auto& pr : pairs)
	{
		const ScanPoint& p = current[pr.current];
		const bool round = pr.round >= 0;
		const ReferencePolyline::LocalLine& L = reference.localLine(pr.a);
		Eigen::Vector3d de;
		const double e = residual(x, c, s, current, reference, pr, &de);
		J += e * e;
		if (residualSpan > 0) scores.emplace_back(pr.current, 2 * e * de);
		// d2J/dx2 = 2 sum (de de^T + e d2e/dx2); on a line only d2e/dw2 =
		// -n.(R p) is non-zero; on a circle the radial unit n also turns
		// as q moves, by P/d (P = I - n n^T, d = |q - o|): d2e/dx2 gains
		// J_q^T P J_q / d, J_q = dq/dx = [I, R'p].
		H += 2 * de * de.transpose();
		const double rx = c * p.x - s * p.y, ry = s * p.x + c * p.y;  // R p
		const double nx = round ? de[0] : L.nx, ny = round ? de[1] : L.ny;
		H(2, 2) += 2 * e * -(nx * rx + ny * ry);
		if (round)
		{
			// J_q^T P J_q = (t, t.R'p)(t, t.R'p)^T, t the tangent at q.
			const Eigen::Vector3d dt = surfaceDirection(c, s, p, reference, pr, de);
			const auto& circle = reference.roundThing(pr.round).circle;
			const double d = std::max(std::hypot(rx + x.x - circle.ox, ry + x.y - circle.oy), 1e-12);
			H += 2 * e * dt * dt.transpose() / d;
		}
		// The surface's normal is estimated: n^ = n - d t, d ~ N(0, s_a^2)
		// its direction error, t the surface's direction where the point
		// pairs (the line's, or the circle's tangent at q). So de carries
		// - d (t, t.R'p), and E[de de^T] exceeds the true term by s_a^2 (t,
		// t.R'p)(t, t.R'p)^T: information that noisy normals invent, along
		// walls above all. Taken out (errors in variables).
		invented += 2 * inventedInformation(x, c, s, current, reference, pr, de);
		// d2J/(dx dz) = 2 (de/dx de/dz + e d2e/(dx dz)).
		uint32_t lo = L.lo;
		if (round)
		{
			const auto& thing = reference.roundThing(pr.round);
			rangeDerivatives(x, p, thing, reference, dedz, &mixed);
			lo = thing.lo;
		}
		else
			rangeDerivatives(x, p, L, reference, dedz, &mixed);
		g[pr.current] += 2 * (de * dedz[0] + e * mixed.col(0));
		for (size_t k = 1; k < dedz.size(); k++)
			g[nc + lo + k - 1] += 2 * (de * dedz[k] + e * mixed.col(static_cast<Eigen::Index>(k)));
		for (double d : dedz) sensitivity += d * d;
	}
	H -= invented;
	information = H;
	if (pairs.size() < 3) return false;
	Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(H);
	const double singular = 1e-12 * std::max(1.0, eig.eigenvalues()[2]);
	if (eig.eigenvalues()[1] <= singular) return false;
	// What is left along the weakest direction must stand out of what the
	// normals' noise invents by chance (its expectation is taken out, its
	// scatter is not): else that direction is unconstrained, as along a
	// corridor's noisy walls, or exactly singular, as along ideal ones.
	const Eigen::Vector3d weakest = eig.eigenvectors().col(0);
	const bool unconstrained = eig.eigenvalues()[0] <= singular ||
		eig.eigenvalues()[0] < kInventedMargin * weakest.dot(invented * weakest);
	Eigen::Vector3d inverse = eig.eigenvalues().cwiseInverse();
	if (unconstrained)
	{
		information -= eig.eigenvalues()[0] * weakest * weakest.transpose();
		inverse[0] = 0;
	}
	const double dof = std::max(1.0, sensitivity - 3);
	const double residualSigma = std::sqrt(J / dof);
	sigma = std::max({minSigma, latticeCellSigma, residualSigma});
	// A range in a shared-error group has its own noise (the residuals')
	// plus the group's one error, which moves the group's ranges together:
	// S = sum_k g_k g_k^T s_k^2 + sum_G (sum_{k in G} g_k)(...)^T s_G^2.
	const double ownSigma = std::max(minSigma, residualSigma);
	Eigen::Matrix3d S = Eigen::Matrix3d::Zero(), Sown = Eigen::Matrix3d::Zero();
	// (group key, sum of its g_k, s_G^2), kept per thread between calls.
	thread_local std::vector<std::tuple<size_t, Eigen::Vector3d, double>> groupSums;
	groupSums.clear();
	for (size_t k = 0; k < g.size(); k++)
	{
		const ScanPoint& p = k < nc ? current[k] : reference.point(static_cast<uint32_t>(k - nc));
		if (p.sharedErrorGroup == 0)
		{
			S += g[k] * g[k].transpose();
			continue;
		}
		Sown += g[k] * g[k].transpose();
		// The two scans' groups apart: the current scan's even keys.
		groupSums.emplace_back(2 * static_cast<size_t>(p.sharedErrorGroup) + (k < nc ? 0 : 1), g[k],
			static_cast<double>(p.sharedRangeSigma) * p.sharedRangeSigma);
	}
	S = S * (sigma * sigma) + Sown * (ownSigma * ownSigma);
	if (!groupSums.empty())
	{
		std::sort(groupSums.begin(), groupSums.end(),
			[](const auto& a, const auto& b) { return std::get<0>(a) < std::get<0>(b); });
		for (size_t i = 0; i < groupSums.size();)
		{
			Eigen::Vector3d sum = Eigen::Vector3d::Zero();
			size_t j = i;
			for (; j < groupSums.size() && std::get<0>(groupSums[j]) == std::get<0>(groupSums[i]); j++)
				sum += std::get<1>(groupSums[j]);
			S += sum * sum.transpose() * std::get<2>(groupSums[i]);
			i = j;
		}
	}
	if (residualSpan > 0) S = upperOf(S, residualScatter(current, scores, residualSpan));
	const Eigen::Matrix3d Hinv =
		eig.eigenvectors() * inverse.asDiagonal() * eig.eigenvectors().transpose();
	cov = Hinv * S * Hinv;
	if (unconstrained) cov += kUnconstrainedVariance * weakest * weakest.transpose();
	cov = 0.5 * (cov + cov.transpose()).eval();
	return true;
}

Eigen::Matrix3d PointToLineCovariance::residualScatter(const std::vector<ScanPoint>& current,
	const std::vector<std::pair<uint32_t, Eigen::Vector3d>>& scores, double span)
{
	// The pairs in the current scan's (bearing) order, each at its arc
	// position: the path along consecutive paired points, a gap wider than
	// the span counting as beyond it. The tent w = max(0, 1 - |ds| / span)
	// is a positive definite kernel on a line (its Fourier transform is a
	// squared sinc), so S_r is positive semi-definite.
	thread_local std::vector<std::pair<uint32_t, Eigen::Vector3d>> byPoint;
	byPoint = scores;
	std::sort(byPoint.begin(), byPoint.end(),
		[](const auto& a, const auto& b) { return a.first < b.first; });
	thread_local std::vector<double> arc;
	arc.assign(byPoint.size(), 0.0);
	for (size_t i = 1; i < byPoint.size(); i++)
	{
		const ScanPoint& a = current[byPoint[i - 1].first];
		const ScanPoint& b = current[byPoint[i].first];
		const double gap = std::hypot(b.x - a.x, b.y - a.y);
		arc[i] = arc[i - 1] + (gap > span ? 2 * span : gap);
	}
	Eigen::Matrix3d out = Eigen::Matrix3d::Zero();
	for (size_t i = 0; i < byPoint.size(); i++)
	{
		out += byPoint[i].second * byPoint[i].second.transpose();
		for (size_t j = i + 1; j < byPoint.size() && arc[j] - arc[i] < span; j++)
		{
			const double w = 1 - (arc[j] - arc[i]) / span;
			const Eigen::Matrix3d cross = byPoint[i].second * byPoint[j].second.transpose();
			out += w * (cross + cross.transpose());
		}
	}
	return out;
}

Eigen::Matrix3d PointToLineCovariance::upperOf(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b)
{
	const Eigen::LLT<Eigen::Matrix3d> llt(a);
	if (llt.info() != Eigen::Success) return a;
	const Eigen::Matrix3d L = llt.matrixL();
	const Eigen::Matrix3d Linv = L.inverse();
	const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(Linv * b * Linv.transpose());
	const Eigen::Vector3d d = eig.eigenvalues().cwiseMax(1.0);
	const Eigen::Matrix3d M = eig.eigenvectors() * d.asDiagonal() * eig.eigenvectors().transpose();
	return L * M * L.transpose();
}
}  // namespace featloc
