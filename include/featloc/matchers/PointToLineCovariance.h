#pragma once
#include <mrpt/math/TPose2D.h>

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "featloc/matchers/ReferencePolyline.h"
#include "featloc/scan/ScanPoints.h"

namespace featloc
{
/** A current point paired with the local line of the reference edge
 * (a, a + 1) (ReferencePolyline::LocalLine), or with the circle of the
 * round thing that edge lies on (ReferencePolyline::RoundThing). */
struct PointToLinePair
{
	uint32_t current = 0;  //!< index into the current points
	uint32_t a = 0;	 //!< edge start in the ReferencePolyline
	int32_t round = -1;	 //!< >= 0: the round thing whose circle it pairs with
};

/** The point-to-line error of a motion and its closed-form covariance
 * (A. Censi, "An accurate closed-form estimate of ICP's covariance",
 * ICRA 2007).
 *
 * With x = (t_x, t_y, w) the motion and z the ranges of every point
 * involved (current points, and the reference points each local line is
 * fitted to), the error is J(x, z) = sum_i e_i^2,
 * e_i = n_i . (R(w) p_i + t - c_i), n_i and c_i the normal and centroid
 * of the pair's local line. The estimate solves dJ/dx = 0, so to first
 * order
 *
 *   cov(x) = H^-1 (sum_k g_k g_k^T s^2) H^-1,
 *   H = d2J/dx2,  g_k = d2J/(dx dz_k)
 *
 * with independent range errors of standard deviation s. The sum runs over
 * the ranges, not the pairs: a reference point in several local lines
 * contributes once, with the sum of its effects. Ranges that share one
 * error (ScanPoint::sharedErrorGroup: a range lattice's run of readings
 * kept on their level) add it once per group,
 * (sum_{k in G} g_k)(sum_{k in G} g_k)^T s_G^2, on top of their own noise:
 * a wall seen head on whose beams all read one level fixes the motion
 * along its normal to the level's rounding error, not to that over the
 * root of its beam count. All derivatives are
 * analytic: a line's centroid moves by 1/m of a point's displacement, its
 * direction (total least squares) by
 * d alpha/d p_j = (cos 2a (d_y, d_x) - sin 2a (d_x, -d_y)) / gap,
 * d = p_j - c, gap the scatter matrix's eigenvalue difference. s is
 * estimated from the residuals (E[J] = s^2 sum_i |de_i/dz|^2), floored at
 * minSigma, so modelling error on real surfaces widens the covariance; on a
 * range lattice (latticeCellSigma > 0: its cell, q / sqrt(12)) the ranges
 * outside any group, the readings put back on their surfaces, take the
 * cell as their least noise (their errors are shared along each chord,
 * which a per-point sigma can only bound). */
class PointToLineCovariance
{
   public:
	/** e and de/d(t_x, t_y, w) for current point p and local line L;
	 * cosPhi, sinPhi: of x.phi (computed once per motion by the caller). */
	static double residual(
		const mrpt::math::TPose2D& x, double cosPhi, double sinPhi, const ScanPoint& p,
		const ReferencePolyline::LocalLine& L, Eigen::Vector3d* gradient = nullptr);

	/** The same on a round thing's circle: e = |q - o| - r. */
	static double residual(
		const mrpt::math::TPose2D& x, double cosPhi, double sinPhi, const ScanPoint& p,
		const ReferencePolyline::RoundThing& thing, Eigen::Vector3d* gradient = nullptr);
	/** The pair's residual, on its line or its circle. */
	static double residual(const mrpt::math::TPose2D& x, double cosPhi, double sinPhi,
		const std::vector<ScanPoint>& current, const ReferencePolyline& reference,
		const PointToLinePair& pair, Eigen::Vector3d* gradient = nullptr);
	/** The variance of the direction of the pair's normal [rad^2]: its
	 * line's directionSigma()^2, or its circle's
	 * (ReferencePolyline::roundNormalVariance) where the point lies. */
	static double normalVariance(const mrpt::math::TPose2D& x, double cosPhi, double sinPhi,
		const std::vector<ScanPoint>& current, const ReferencePolyline& reference,
		const PointToLinePair& pair);
	/** The residual's gradient with the surface's direction t in place of
	 * its normal, (t, t.R'p): t the line's direction, or the circle's
	 * tangent at the point (from `gradient`, the pair's residual gradient). */
	static Eigen::Vector3d surfaceDirection(double cosPhi, double sinPhi, const ScanPoint& p,
		const ReferencePolyline& reference, const PointToLinePair& pair,
		const Eigen::Vector3d& gradient);
	/** The information the pair's normal's error invents on average,
	 * normalVariance() (t, t.R'p)(t, t.R'p)^T (surfaceDirection), for the
	 * error e^2; compute() takes twice it, its J being sum e^2 with
	 * derivatives 2 e de. */
	static Eigen::Matrix3d inventedInformation(const mrpt::math::TPose2D& x, double cosPhi,
		double sinPhi, const std::vector<ScanPoint>& current, const ReferencePolyline& reference,
		const PointToLinePair& pair, const Eigen::Vector3d& gradient);
	/** Whether `information` fixes every direction: its weakest eigenvalue
	 * above kInventedMargin times what `invented` puts along it (compute()'s
	 * test, without its singularity floor). */
	static bool fixesEveryDirection(const Eigen::Matrix3d& information, const Eigen::Matrix3d& invented);

	/** de/dz for the current point's range (first) and for each point
	 * lo..hi of L (following), analytic; for tests and compute(). Also
	 * d(de/dx)/dz in `mixed` (3 x (1 + points)) when given. */
	static void rangeDerivatives(
		const mrpt::math::TPose2D& x, const ScanPoint& p,
		const ReferencePolyline::LocalLine& L, const ReferencePolyline& reference,
		std::vector<double>& dedz, Eigen::Matrix<double, 3, Eigen::Dynamic>* mixed = nullptr);
	/** The same on a round thing's circle, for each of its points lo..hi:
	 * the reference ranges act through the circle's fit, d(ox, oy, r)/dz_j
	 * = -(A^T A)^-1 a_j (n_j.u_j) (CircleFit), and de/d(ox, oy, r) = (-n,
	 * -1). */
	static void rangeDerivatives(const mrpt::math::TPose2D& x, const ScanPoint& p,
		const ReferencePolyline::RoundThing& thing, const ReferencePolyline& reference,
		std::vector<double>& dedz, Eigen::Matrix<double, 3, Eigen::Dynamic>* mixed = nullptr);

	/** Errors in variables: each local line's normal is itself estimated
	 * (ReferencePolyline::directionSigma), and H built from estimated
	 * normals exceeds the true one by sum 2 s_a^2 g_t g_t^T on average
	 * (g_t the residual's gradient with the line's direction in place of
	 * its normal): along a corridor's noisy walls, that alone made the
	 * motion along the corridor look known to millimetres. It is taken out
	 * of H, and the weakest direction of what is left must carry at least
	 * kInventedMargin times that invented information, or it counts as
	 * unconstrained.
	 *
	 * The covariance of such a direction, or of the one direction along
	 * which H is singular (ideal walls of a corridor), is
	 * kUnconstrainedVariance (the caller's max_translation_sigma test then
	 * names it), the other two directions keep theirs; `information` has
	 * its eigenvalue zeroed. False when H is singular in two directions or
	 * more (the pairs do not constrain the motion); `information` receives
	 * H either way. */
	static constexpr double kInventedMargin = 2.0;
	static constexpr double kUnconstrainedVariance = 1e4;  //!< [m^2 or rad^2]
	/** Pairs with round things (PointToLinePair::round) count alike: e =
	 * |q - o| - r, the reference ranges acting through the circle's fit,
	 * and the normal's variance through its centre's.
	 *
	 * residualSpan > 0 [m]: the modelled scatter of the gradient,
	 * sum_k g_k g_k^T s^2 (S), is compared with what the residuals show,
	 * S_r = sum_ij w_ij u_i u_j^T, u_i = 2 e_i de_i/dx, w_ij = max(0, 1 -
	 * |s_i - s_j| / residualSpan), s the current points' arc position
	 * along the scan (a gap wider than the span breaks it): a surface that
	 * departs from its local lines (rough rock, a polygon's facets under a
	 * bowed line) leaves residuals that run together over a stretch of it,
	 * whose effects on the motion add up instead of averaging out, which
	 * a per-point s cannot show. Along every direction where S_r exceeds S
	 * it takes its place (the smallest matrix above both). 0: S alone. */
	static bool compute(
		const std::vector<ScanPoint>& current, const ReferencePolyline& reference,
		const std::vector<PointToLinePair>& pairs, const mrpt::math::TPose2D& x,
		double minSigma, double latticeCellSigma, Eigen::Matrix3d& cov, double& sigma,
		Eigen::Matrix3d& information, double residualSpan = 0);

	/** The residuals' own gradient scatter S_r of compute() (pairs with
	 * their u_i, any order; the current points give the arc positions). */
	static Eigen::Matrix3d residualScatter(const std::vector<ScanPoint>& current,
		const std::vector<std::pair<uint32_t, Eigen::Vector3d>>& scores, double span);
	/** An upper bound of a and b in the Loewner order (a positive
	 * definite): with a = L L^T and L^-1 b L^-T = V D V^T, L V max(1, D)
	 * V^T L^T. It is a where b lies below a, and takes b's size along the
	 * directions where b exceeds a. */
	static Eigen::Matrix3d upperOf(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b);
};
}  // namespace featloc
