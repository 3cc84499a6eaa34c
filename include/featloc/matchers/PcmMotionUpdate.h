#pragma once
#include <mrpt/math/TPose2D.h>

#include <cstdint>
#include <vector>

#include "featloc/features/ScanFeature.h"

namespace featloc
{
/** One reference/current feature pair with its PCM membership mu_ij. */
struct FeaturePair
{
	uint32_t i;	 //!< reference feature (scan k-1)
	uint32_t j;	 //!< current feature (scan k)
	double mu;
};

/** The motion step of Borges & Aldon's PCM matcher: with the memberships
 * mu_ij fixed, the (t, w) minimising
 *   E = sum_ij mu_ij || f_j - R(w) (f_i - A_i t) ||^2        (eqs. 9-12)
 * in closed form (eqs. 15-23).
 *
 * Derivation (frame k = R(w)(frame k-1 - t), R as eq. (2)): dE/dt = 0 gives
 * eq. (16), t = M^-1 (N beta + q), beta = (cos w, sin w), with
 * M = sum mu A_i (A_i is a projection for lines, so the printed eq. (18)
 * equals this), N = -sum mu A_i [x_j -y_j; y_j x_j], q = sum mu A_i f_i.
 * dE/dw = 0 gives eq. (17), beta^T r + beta^T P t = 0 with
 * r = sum mu (y_i x_j - x_i y_j, -x_i x_j - y_i y_j) and
 * P = [0 1; -1 0] N^T. Substituting t:
 *   beta^T (P M^-1 N) beta + beta^T (r + P M^-1 q) = 0;
 * the printed eq. (23) drops the q. With c = cos w, z = sin w this is
 * U(z) + c V(z) = 0, U = Q00 + s1 z + (Q11 - Q00) z^2, V = s0 + (Q01 + Q10) z
 * (Q = P M^-1 N, s = r + P M^-1 q); squaring, U^2 - (1 - z^2) V^2 = 0, a
 * quartic in z. Each real root in [-1, 1] gives w = asin(z) and pi - asin(z);
 * the candidate with the least E wins, and t follows from eq. (16).
 *
 * `damping` adds damping * ||t - t_prev||^2 to E (a tiny multiple of
 * trace(M)): when the features leave a direction unconstrained (parallel
 * corridor walls), t stays where it was along it instead of M being
 * singular.
 *
 * Rotation window: with windowHalfWidth > 0, only candidates within
 * windowHalfWidth of windowCentre are considered (the method assumes the
 * motion lies in the validity interval around the initial estimate; without
 * it, a pi - w candidate can win on E with symmetric geometry). */
class PcmMotionUpdate
{
   public:
	/** Minimises E; returns the new (t_x, t_y, w). `previous` is the
	 * current estimate (used for the damping term only). */
	static mrpt::math::TPose2D solve(
		const std::vector<ScanFeature>& reference,
		const std::vector<ScanFeature>& current,
		const std::vector<FeaturePair>& pairs,
		const mrpt::math::TPose2D& previous, double damping = 1e-9,
		double windowCentre = 0, double windowHalfWidth = 0);

	/** E at (t, w). */
	static double cost(
		const std::vector<ScanFeature>& reference,
		const std::vector<ScanFeature>& current,
		const std::vector<FeaturePair>& pairs, const mrpt::math::TPose2D& motion);

	/** lambda(f_i, t, w) = R(w) (f_i - A_i t), eq. (11). */
	static void predict(
		const ScanFeature& f, const mrpt::math::TPose2D& motion, double& x,
		double& y);
	/** The same with cos w and sin w given (one rotation, many features). */
	static void predict(const ScanFeature& f, const mrpt::math::TPose2D& motion, double cw,
		double sw, double& x, double& y);
};
}  // namespace featloc
