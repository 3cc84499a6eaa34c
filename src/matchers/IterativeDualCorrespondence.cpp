#include "featloc/matchers/IterativeDualCorrespondence.h"

#include <mrpt/math/wrap2pi.h>
#include <mrpt/tfest/se2.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "featloc/config/ConfigValues.h"
#include "featloc/matchers/MotionConstraintCheck.h"

namespace featloc
{
void IterativeDualCorrespondence::Parameters::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	using namespace featloc::config;
	read(c, s, "max_iterations", max_iterations);
	read(c, s, "error_ratio", error_ratio);
	read(c, s, "window_sigmas", window_sigmas);
	readDegrees(c, s, "min_bearing_window_DEG", min_bearing_window);
	read(c, s, "min_pair_distance", min_pair_distance);
	read(c, s, "max_pair_distance", max_pair_distance);
	read(c, s, "window_iterations", window_iterations);
	read(c, s, "dual_decimation", dual_decimation);
	read(c, s, "min_pairs", min_pairs);
	readChoice(c, s, "final_phase", final_phase, {"point_to_line", "idc"});
	read(c, s, "step_tolerance", step_tolerance);
	read(c, s, "line_half_window", line_half_window);
	readDegrees(c, s, "max_line_direction_sigma_DEG", max_line_direction_sigma);
	readDegrees(c, s, "max_face_direction_sigma_DEG", max_face_direction_sigma);
	read(c, s, "face_segment_extent", face_segment_extent);
	read(c, s, "grow_lines_to_direction_sigma", grow_lines_to_direction_sigma);
	read(c, s, "line_bow_sigmas", line_bow_sigmas);
	read(c, s, "guess_gate_chi2", guess_gate_chi2);
	read(c, s, "covariance_inflation", covariance_inflation);
	read(c, s, "min_range_sigma", min_range_sigma);
	read(c, s, "max_translation_sigma", max_translation_sigma);
	readDegrees(c, s, "max_rotation_sigma_DEG", max_rotation_sigma);
	require(max_iterations >= 1, c, s, "max_iterations", ">= 1");
	require(error_ratio > 0, c, s, "error_ratio", "> 0");
	require(window_sigmas > 0, c, s, "window_sigmas", "> 0");
	require(min_bearing_window > 0, c, s, "min_bearing_window_DEG", "> 0");
	require(min_pair_distance > 0, c, s, "min_pair_distance", "> 0");
	require(max_pair_distance >= min_pair_distance, c, s, "max_pair_distance",
		">= min_pair_distance");
	require(min_pairs >= 3, c, s, "min_pairs", ">= 3");
	require(dual_decimation >= 1, c, s, "dual_decimation", ">= 1");
	require(step_tolerance > 0, c, s, "step_tolerance", "> 0");
	require(line_half_window >= 1, c, s, "line_half_window", ">= 1");
	require(max_line_direction_sigma > 0, c, s, "max_line_direction_sigma_DEG", "> 0");
	require(max_face_direction_sigma >= 0, c, s, "max_face_direction_sigma_DEG", ">= 0 (0 disables it)");
	require(face_segment_extent > 0, c, s, "face_segment_extent", "> 0");
	require(line_bow_sigmas >= 0, c, s, "line_bow_sigmas", ">= 0 (0 disables it)");
	require(guess_gate_chi2 >= 0, c, s, "guess_gate_chi2", ">= 0 (0 disables it)");
	require(covariance_inflation >= 1, c, s, "covariance_inflation", ">= 1");
	require(min_range_sigma > 0, c, s, "min_range_sigma", "> 0");
	require(max_translation_sigma > 0, c, s, "max_translation_sigma", "> 0");
	require(max_rotation_sigma > 0, c, s, "max_rotation_sigma_DEG", "> 0");
}

void IterativeDualCorrespondence::Parameters::saveToConfigFile(
	mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	using namespace featloc::config;
	write(c, s, "max_iterations", max_iterations,
		"IDC: failure (no convergence) after this many iterations (paper: 500)");
	write(c, s, "error_ratio", error_ratio,
		"IDC: converged when the mean squared pair distance changes by less than this, relative (paper: 1e-6)");
	write(c, s, "window_sigmas", window_sigmas,
		"IDC: initial bearing window B_0 and pair distance D_0, in standard deviations of the guess");
	writeDegrees(c, s, "min_bearing_window_DEG", min_bearing_window,
		"[deg] IDC: smallest bearing window of the matching-range rule");
	write(c, s, "min_pair_distance", min_pair_distance,
		"[m] IDC: smallest pair distance threshold (pairs farther apart are outliers)");
	write(c, s, "max_pair_distance", max_pair_distance, "[m] IDC: cap of D_0");
	write(c, s, "window_iterations", window_iterations,
		"IDC: the windows shrink geometrically to their minima, reached at this iteration");
	write(c, s, "dual_decimation", dual_decimation,
		"final_phase = point_to_line: the dual rules use every N-th current point (the last phase uses all)");
	write(c, s, "min_pairs", min_pairs, "IDC: failure below this many closest-point pairs");
	write(c, s, "final_phase", final_phase,
		"point_to_line (Gauss-Newton on the point-to-line error once the windows are at their minima) | idc (the paper)");
	write(c, s, "step_tolerance", step_tolerance,
		"point_to_line phase: converged when a step is below this many standard deviations of the estimate");
	write(c, s, "line_half_window", line_half_window,
		"point_to_line phase: a reference edge's local line takes up to this many neighbours on each side, while they stay within 3 sigma of it");
	writeDegrees(c, s, "max_line_direction_sigma_DEG", max_line_direction_sigma,
		"[deg] point_to_line phase: points pair only with local lines whose direction is known this well (noise / sqrt(scatter along the line))");
	writeDegrees(c, s, "max_face_direction_sigma_DEG", max_face_direction_sigma,
		"[deg] point_to_line phase: on a segment of at least face_segment_extent, points pair with local lines whose direction is known this well instead: a large structure's short faces (door jambs, steps), which cannot grow past their corners (0 = off: max_line_direction_sigma_DEG for all, as until 2026-12-03)");
	write(c, s, "face_segment_extent", face_segment_extent,
		"[m] point_to_line phase: a segment this long (first to last point) takes max_face_direction_sigma_DEG; shorter ones (a leg, a trunk, a pole) keep max_line_direction_sigma_DEG");
	write(c, s, "grow_lines_to_direction_sigma", grow_lines_to_direction_sigma,
		"point_to_line phase: a local line whose direction is still known worse than max_line_direction_sigma_DEG after line_half_window grows on until it is not (up to 8x as many points), instead of being left out: dense noisy scans (false: as until 2026-12-01)");
	write(c, s, "line_bow_sigmas", line_bow_sigmas,
		"point_to_line phase: a local line whose points bow away from it by more than this many standard errors of the quadratic term keeps the bow (a local parabola): on curved walls a chord biases the heading (0 = off: straight lines only, as until 2026-12-03)");
	write(c, s, "guess_gate_chi2", guess_gate_chi2,
		"failure when the estimate's Mahalanobis^2 from the initial guess exceeds this (21.1: 99.99% for 3 dof; 0 = off)");
	write(c, s, "covariance_inflation", covariance_inflation,
		"covariance: Censi's closed form (fixed correspondences) times this; re-pairing noisy points adds variance");
	write(c, s, "min_range_sigma", min_range_sigma,
		"[m] covariance: floor of the range noise estimated from the residuals");
	write(c, s, "max_translation_sigma", max_translation_sigma,
		"[m] failure when the estimate's sigma along its weakest translation direction exceeds this");
	writeDegrees(c, s, "max_rotation_sigma_DEG", max_rotation_sigma,
		"[deg] failure when the estimate's rotation sigma exceeds this");
}

namespace
{
/** x (+) p: the point p of the current frame in the reference frame. */
inline void transform(
	double c, double s, const mrpt::math::TPose2D& x, const ScanPoint& p, double& qx, double& qy)
{
	qx = c * p.x - s * p.y + x.x;
	qy = s * p.x + c * p.y + x.y;
}

/** The least-squares rigid motion taking the first points of `pairs` onto
 * the second ones (MRPT's closed form, Horn's method in 2-D). */
mrpt::math::TPose2D rigidMotion(const std::vector<Eigen::Vector4d>& pairs)
{
	mrpt::tfest::TMatchingPairList corrs;
	corrs.reserve(pairs.size());
	for (size_t k = 0; k < pairs.size(); k++)
	{
		const auto& p = pairs[k];
		corrs.emplace_back(static_cast<uint32_t>(k), static_cast<uint32_t>(k),
			mrpt::math::TPoint3Df(static_cast<float>(p[2]), static_cast<float>(p[3]), 0),
			mrpt::math::TPoint3Df(static_cast<float>(p[0]), static_cast<float>(p[1]), 0));
	}
	mrpt::math::TPose2D t;
	mrpt::tfest::se2_l2(corrs, t);
	return t;
}
}  // namespace

double IterativeDualCorrespondence::medianDistance(
	const ReferencePolyline& reference, const ScanPoint* current, size_t n,
	const mrpt::math::TPose2D& x, double maxDistance)
{
	if (n == 0) return maxDistance;
	std::vector<double> d(n);
	const double c = std::cos(x.phi), s = std::sin(x.phi);
	for (size_t i = 0; i < n; i++)
	{
		double qx, qy;
		transform(c, s, x, current[i], qx, qy);
		ReferencePolyline::Hit hit;
		d[i] = reference.closestPoint({qx, qy}, maxDistance, hit) ? hit.distance : maxDistance;
	}
	auto mid = d.begin() + static_cast<long>(n / 2);
	std::nth_element(d.begin(), mid, d.end());
	return *mid;
}

bool IterativeDualCorrespondence::pointToLineStep(
	const ReferencePolyline& reference, const std::vector<ScanPoint>& current,
	mrpt::math::TPose2D& x, double& stepSigmas) const
{
	if (m_lines.size() < 3) return false;
	const double c = std::cos(x.phi), s = std::sin(x.phi);
	double meanSquare = 0;
	Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
	Eigen::Vector3d b = Eigen::Vector3d::Zero();
	for (const auto& pr : m_lines)
	{
		Eigen::Vector3d g;
		const double e =
			PointToLineCovariance::residual(x, c, s, current[pr.current], reference.localLine(pr.a), &g);
		A += g * g.transpose();
		b += g * e;
		meanSquare += e * e;
	}
	meanSquare /= static_cast<double>(m_lines.size());
	// A little damping keeps an unconstrained direction (a corridor) where
	// it is; the covariance check reports it.
	A.diagonal().array() += 1e-9 * (1 + A.trace());
	const Eigen::Vector3d d = -A.ldlt().solve(b);
	if (!d.allFinite()) return false;
	x = {x.x + d[0], x.y + d[1], mrpt::math::wrapToPi(x.phi + d[2])};
	// The step in standard deviations of the estimate (cov ~ s^2 A^-1, s^2
	// the mean squared residual).
	stepSigmas = std::sqrt(d.dot(A * d) / std::max(meanSquare, 1e-24));
	return true;
}

void IterativeDualCorrespondence::run(
	const ReferencePolyline& reference, const std::vector<ScanPoint>& current,
	const mrpt::poses::CPosePDFGaussian& guess, Result& r, const PhaseSwitch& onPointToLine,
	const Revision& onConverged)
{
	r = Result();
	mrpt::math::TPose2D x(guess.mean.x(), guess.mean.y(), guess.mean.phi());
	r.estimate = x;

	// Initial windows from the guess's uncertainty; a translation error and a
	// rotation error seen at the median range both separate true pairs.
	const auto& G = guess.cov;
	const double sxy = std::sqrt(std::max({G(0, 0), G(1, 1), 0.0}));
	const double sw = std::sqrt(std::max(G(2, 2), 0.0));
	m_ranges.clear();
	for (const auto& p : current) m_ranges.push_back(p.range);
	double medianRange = 0;
	if (!m_ranges.empty())
	{
		auto mid = m_ranges.begin() + static_cast<long>(m_ranges.size() / 2);
		std::nth_element(m_ranges.begin(), mid, m_ranges.end());
		medianRange = *mid;
	}
	const double B0 =
		std::clamp(params.window_sigmas * sw, params.min_bearing_window, M_PI / 2);
	const double D0 = std::clamp(params.window_sigmas * (sxy + sw * medianRange),
		params.min_pair_distance, params.max_pair_distance);
	const double n_s = std::max(1u, params.window_iterations);

	// The dual rules while the windows shrink (and after, for the paper's
	// IDC), then point-to-line steps.
	bool dual = true;
	// Errors of the last iterations of this phase, newest first (-1: none):
	// a cycle of up to this many iterations is caught (one of 10 was seen
	// where a weakly constrained direction lets points change lines, one of
	// 22 on the Radish belgioioso log, pair 103 of featloc-bench --seed 1:
	// poses 7 mm and 0.2 deg apart, for ever).
	std::array<double, 64> previousErrors;
	previousErrors.fill(-1);
	double D = D0;
	bool converged = false;
	const bool pointToLine = params.final_phase == "point_to_line";
	m_closestHint.assign(current.size(), ReferencePolyline::kNoHint);
	m_rangeHint.assign(current.size(), ReferencePolyline::kNoHint);
	double lastRotation = M_PI, lastTranslation = 1e9;	// the last dual step
	// Converged, unless the caller changes the point sets once more at the
	// point-to-line phase's end (then the iterations go on from there).
	bool refined = false;
	auto settled = [&] {
		if (!dual && onConverged && !refined)
		{
			refined = true;
			if (onConverged(x))
			{
				previousErrors.fill(-1);
				m_closestHint.assign(current.size(), ReferencePolyline::kNoHint);
				return false;
			}
		}
		converged = true;
		return true;
	};
	for (unsigned int k = 0; k < params.max_iterations && !converged; k++)
	{
		const double f = std::min(1.0, static_cast<double>(k) / n_s);
		double B = B0 * std::pow(params.min_bearing_window / B0, f);
		D = D0 * std::pow(params.min_pair_distance / D0, f);
		if (pointToLine && dual)
		{
			// featloc: no wider than what the last step says is left to find.
			B = std::max(params.min_bearing_window, std::min(B, params.window_sigmas * lastRotation));
			D = std::max(params.min_pair_distance,
				std::min(D, params.window_sigmas * (lastTranslation + lastRotation * medianRange)));
		}
		const bool atMinima = k >= params.window_iterations ||
			(B <= params.min_bearing_window && D <= params.min_pair_distance);
		if (dual && atMinima && pointToLine)
		{
			dual = false;
			previousErrors.fill(-1);
			if (onPointToLine)
			{
				// The caller may change both point sets here.
				onPointToLine(x);
				m_closestHint.assign(current.size(), ReferencePolyline::kNoHint);
			}
		}

		const double c = std::cos(x.phi), s = std::sin(x.phi);
		m_cp.clear();
		m_mrp.clear();
		m_lines.clear();
		m_lineDistances.clear();
		// The dual rules only bring the estimate near the solution: with
		// the point-to-line phase to follow, every dual_decimation-th point
		// is enough for them.
		const size_t stride = dual && pointToLine ? params.dual_decimation : 1;
		const size_t used = (current.size() + stride - 1) / stride;
		for (size_t i = 0; i < current.size(); i += stride)
		{
			const ScanPoint& p = current[i];
			double qx, qy;
			transform(c, s, x, p, qx, qy);
			const ReferencePolyline::Query q(qx, qy);
			ReferencePolyline::Hit hit;
			if (reference.closestPoint(q, D, hit, m_closestHint[i]))
			{
				m_closestHint[i] = hit.a;
				m_cp.emplace_back(qx, qy, hit.x, hit.y);
				// Point-to-line pairs need a line fitted to three points at
				// least (a two-point edge whose neighbours both leave its
				// line bridges two surfaces: a depth jump at long range that
				// the breakpoint test let through) and whose direction is
				// known: a line of a few noisy points close together has a
				// random normal, and a wall's random normals constrain the
				// motion along the wall that nothing constrains. (A large
				// structure's short faces pair known less well:
				// lineDirectionGate.)
				const ReferencePolyline::LocalLine* L =
					hit.a != hit.b ? &reference.localLine(hit.a) : nullptr;
				if (L && L->hi - L->lo >= 2 &&
					reference.directionSigma(hit.a) <=
						params.lineDirectionGate(reference.segmentExtent(hit.a)))
				{
					m_lines.push_back({static_cast<uint32_t>(i), hit.a});
					m_lineDistances.push_back(std::abs(L->nx * (qx - L->cx) + L->ny * (qy - L->cy)));
				}
			}
			// The range rule's pair must lie within D as well, so its window
			// need not reach beyond the bearings D covers.
			const double window = q.range > D ? std::min(B, std::asin(D / q.range)) : B;
			if (dual && reference.matchingRangePoint(q, window, hit, m_rangeHint[i]))
			{
				m_rangeHint[i] = hit.a;
				if (hit.distance <= D) m_mrp.emplace_back(qx, qy, hit.x, hit.y);
			}
		}
		r.pairs = m_cp.size();
		if (m_cp.size() * stride < params.min_pairs)
		{
			char buf[200];
			std::snprintf(buf, sizeof(buf),
				"too few pairs: %zu of %zu points within %.2f m of the reference (min_pairs %u)",
				m_cp.size(), used, D, params.min_pairs);
			r.failureReason = buf;
			r.estimate = x;
			return;
		}
		// The error: mean squared distance of the pairs the step uses.
		double error = 0;
		if (dual)
		{
			for (const auto& p : m_cp) error += (p.head<2>() - p.tail<2>()).squaredNorm();
			error /= static_cast<double>(m_cp.size());
		}
		else
		{
			for (double d : m_lineDistances) error += d * d;
			error /= static_cast<double>(std::max<size_t>(1, m_lineDistances.size()));
		}

		// The paper's test against the previous error and, at the windows'
		// minima, against the errors of a few iterations back: a
		// correspondence flipping between edges at a corner makes the
		// iteration cycle through two or three estimates microns apart for
		// ever.
		auto same = [&](double before) {
			return before >= 0 && std::abs(before - error) <= params.error_ratio * before;
		};
		bool repeats = same(previousErrors[0]) || error < 1e-24;
		for (size_t j = 1; atMinima && j < previousErrors.size(); j++)
			repeats = repeats || same(previousErrors[j]);
		if (repeats)
		{
			if (settled()) break;
			continue;
		}
		std::rotate(previousErrors.rbegin(), previousErrors.rbegin() + 1, previousErrors.rend());
		previousErrors[0] = error;
		r.iterations++;

		const mrpt::math::TPose2D before = x;
		if (!dual)
		{
			double stepSigmas = 0;
			if (!pointToLineStep(reference, current, x, stepSigmas))
			{
				r.failureReason = "only " + std::to_string(m_lines.size()) +
					" points lie near reference lines of three points or more: the motion is "
					"not constrained";
				r.estimate = x;
				return;
			}
			if (stepSigmas < params.step_tolerance)
			{
				if (settled()) break;
				continue;
			}
		}
		else
		{
			// Lu & Milios: rotation of the range rule, translation of the
			// closest-point rule's own solution.
			const mrpt::math::TPose2D closest = rigidMotion(m_cp);
			const double w2 = m_mrp.size() >= 2 ? rigidMotion(m_mrp).phi : closest.phi;
			const Eigen::Vector2d T1(closest.x, closest.y);
			const double c2 = std::cos(w2), s2 = std::sin(w2);
			x = mrpt::math::TPose2D(c2 * x.x - s2 * x.y + T1.x(), s2 * x.x + c2 * x.y + T1.y(),
				mrpt::math::wrapToPi(x.phi + w2));
			lastRotation = std::abs(w2);
			lastTranslation = std::hypot(x.x - before.x, x.y - before.y);
		}
		if (atMinima && std::hypot(x.x - before.x, x.y - before.y) < 1e-7 &&
			std::abs(mrpt::math::wrapToPi(x.phi - before.phi)) < 1e-7 && settled())
			break;
	}
	r.estimate = x;
	if (!converged)
	{
		char buf[160];
		std::snprintf(buf, sizeof(buf), "no convergence in %u iterations (max_iterations)",
			params.max_iterations);
		r.failureReason = buf;
		return;
	}

	// The covariance from the last pairing: the loop ends right after it,
	// or one step shorter than step_tolerance sigmas (or 1e-7) later.
	const MotionConstraintCheck check(params.max_translation_sigma, params.max_rotation_sigma,
		"the paired points", "all paired surfaces parallel to it, as in a corridor");
	Eigen::Matrix3d H;
	if (!PointToLineCovariance::compute(
			current, reference, m_lines, x, params.min_range_sigma, rangeLatticeCellSigma, r.cov,
			r.rangeSigma, H))
	{
		r.failureReason = m_lines.size() < 3 ? "" : check.singular(H);
		if (r.failureReason.empty())
			r.failureReason = "fewer than 3 points paired with reference edges: the motion is "
							  "not constrained";
		return;
	}
	r.cov *= params.covariance_inflation;
	r.failureReason = check.tooUncertain(r.cov);
	r.success = r.failureReason.empty();
	if (r.success) return;
	// Is it one direction only? The covariance the estimate would have if
	// its position along the most uncertain direction w were known is
	// C - C w w^T C / (w^T C w); if that passes, the pairs fix the rest.
	const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(r.cov);
	const Eigen::Vector3d w = eig.eigenvectors().col(2);
	const Eigen::Vector3d Cw = r.cov * w;
	if (check.tooUncertain(r.cov - Cw * Cw.transpose() / w.dot(Cw)).empty())
		r.freeDirection = w;
}
}  // namespace featloc
