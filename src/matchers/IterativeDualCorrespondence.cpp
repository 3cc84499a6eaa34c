#include "featloc/matchers/IterativeDualCorrespondence.h"

#include <mrpt/math/distributions.h>
#include <mrpt/math/wrap2pi.h>
#include <mrpt/tfest/se2.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>

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
	read(c, s, "line_bow_per_segment", line_bow_per_segment);
	read(c, s, "circle_fit_sigmas", circle_fit_sigmas);
	read(c, s, "guess_gate_chi2", guess_gate_chi2);
	read(c, s, "covariance_inflation", covariance_inflation);
	read(c, s, "min_range_sigma", min_range_sigma);
	read(c, s, "covariance_residual_span", covariance_residual_span);
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
	require(circle_fit_sigmas >= 0, c, s, "circle_fit_sigmas", ">= 0 (0 disables it)");
	require(guess_gate_chi2 >= 0, c, s, "guess_gate_chi2", ">= 0 (0 disables it)");
	require(covariance_inflation >= 1, c, s, "covariance_inflation", ">= 1");
	require(min_range_sigma > 0, c, s, "min_range_sigma", "> 0");
	require(covariance_residual_span >= 0, c, s, "covariance_residual_span", ">= 0 (0 disables it)");
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
	write(c, s, "line_bow_per_segment", line_bow_per_segment,
		"point_to_line phase, with line_bow_sigmas: a segment whose lines, one window apart, bow one way (their median t beyond line_bow_sigmas) keeps every line's bow: a round wall's chords bias the motion together (a switch, off: it broke the rotunda's whole matcher-chain runs)");
	write(c, s, "circle_fit_sigmas", circle_fit_sigmas,
		"point_to_line phase: a segment shorter than face_segment_extent that a circle fits better than a line by more than this many sigmas (and within its noise) is a small round thing: its points pair with the circle (a trunk's few points give lines of unknown direction; 0 = off: lines only, as until 2026-12-04)");
	write(c, s, "guess_gate_chi2", guess_gate_chi2,
		"failure when the estimate's Mahalanobis^2 from the initial guess exceeds this (21.1: 99.99% for 3 dof; 0 = off)");
	write(c, s, "covariance_inflation", covariance_inflation,
		"covariance: Censi's closed form (fixed correspondences) times this; re-pairing noisy points adds variance");
	write(c, s, "min_range_sigma", min_range_sigma,
		"[m] covariance: floor of the range noise estimated from the residuals");
	write(c, s, "covariance_residual_span", covariance_residual_span,
		"[m] covariance: the residuals' own scatter of the gradient, pairs within this arc of each other counted together (a surface that departs from its local lines over a stretch), bounds Censi's from below (0 = off)");
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

bool IterativeDualCorrespondence::pointToLineStep(const ReferencePolyline& reference,
	const std::vector<ScanPoint>& current, const std::vector<PointToLinePair>& pairs,
	mrpt::math::TPose2D& x, double& stepSigmas)
{
	if (pairs.size() < 3) return false;
	const double c = std::cos(x.phi), s = std::sin(x.phi);
	double meanSquare = 0;
	Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
	Eigen::Vector3d b = Eigen::Vector3d::Zero();
	for (const auto& pr : pairs)
	{
		Eigen::Vector3d g;
		const double e = PointToLineCovariance::residual(x, c, s, current, reference, pr, &g);
		A += g * g.transpose();
		b += g * e;
		meanSquare += e * e;
	}
	meanSquare /= static_cast<double>(pairs.size());
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

bool IterativeDualCorrespondence::pointToLinePair(const ReferencePolyline& reference,
	const ReferencePolyline::Hit& hit, uint32_t i, double qx, double qy,
	const std::vector<char>& skipRound, PointToLinePair& pair, double& distance) const
{
	// Point-to-line pairs need a line fitted to three points at least (a
	// two-point edge whose neighbours both leave its line bridges two
	// surfaces: a depth jump at long range that the breakpoint test let
	// through) and whose direction is known: a line of a few noisy points
	// close together has a random normal, and a wall's random normals
	// constrain the motion along the wall that nothing constrains. (A large
	// structure's short faces pair known less well: lineDirectionGate.)
	if (hit.a == hit.b) return false;
	// A round thing's points pair with its circle, which knows its normals
	// as well as its centre (unless it may have moved:
	// dropMovedRoundThing; its points then go to their lines).
	const int32_t round = reference.roundOf(hit.a);
	if (round >= 0 && !skipRound[static_cast<size_t>(round)])
	{
		pair = {i, hit.a, round};
		distance = reference.roundThing(round).distance(qx, qy);
		return true;
	}
	const ReferencePolyline::LocalLine& L = reference.localLine(hit.a);
	if (L.hi - L.lo < 2 ||
		reference.directionSigma(hit.a) > params.lineDirectionGate(reference.segmentExtent(hit.a)))
		return false;
	pair = {i, hit.a};
	distance = std::abs(L.nx * (qx - L.cx) + L.ny * (qy - L.cy));
	return true;
}

double IterativeDualCorrespondence::leftOutGroupRatio(const ReferencePolyline& reference,
	const std::vector<ScanPoint>& current, const mrpt::math::TPose2D& x, double D, size_t first,
	size_t end, int32_t group)
{
	// The point-to-line phase again from x without the group (and without
	// the things already dropped), re-pairing at each step: one linearised
	// step is not enough, where the lines' points change lines as the
	// estimate moves (a corridor's walls weakly fixing the motion along
	// it, a person's legs walking with the robot).
	std::vector<char>& skip = m_looSkip;
	skip = m_roundDropped;
	for (size_t k = 0; k < skip.size(); k++)
		if (m_looGroup[k] == group) skip[k] = 1;
	mrpt::math::TPose2D xk = x;
	std::vector<PointToLinePair>& pairs = m_looPairs;
	auto pairAt = [&](const mrpt::math::TPose2D& at) {
		pairs.clear();
		const double c = std::cos(at.phi), s = std::sin(at.phi);
		for (size_t i = 0; i < current.size(); i++)
		{
			double qx, qy;
			transform(c, s, at, current[i], qx, qy);
			ReferencePolyline::Hit hit;
			PointToLinePair pair;
			double distance;
			if (reference.closestPoint({qx, qy}, D, hit, m_closestHint[i]) &&
				pointToLinePair(reference, hit, static_cast<uint32_t>(i), qx, qy, skip, pair, distance))
				pairs.push_back(pair);
		}
	};
	for (unsigned int it = 0; it < kLeftOutIterations; it++)
	{
		pairAt(xk);
		double stepSigmas = 0;
		if (!pointToLineStep(reference, current, pairs, xk, stepSigmas))
			return std::numeric_limits<double>::infinity();
		if (stepSigmas < params.step_tolerance) break;
	}
	pairAt(xk);
	// The others' information there, less what noisy normals invent: it
	// must still fix every direction, and gives that estimate's
	// covariance.
	const double c = std::cos(xk.phi), s = std::sin(xk.phi);
	Eigen::Matrix3d A = Eigen::Matrix3d::Zero(), invented = Eigen::Matrix3d::Zero();
	for (const auto& pr : pairs)
	{
		Eigen::Vector3d g;
		PointToLineCovariance::residual(xk, c, s, current, reference, pr, &g);
		A += g * g.transpose();
		invented += PointToLineCovariance::inventedInformation(xk, c, s, current, reference, pr, g);
	}
	if (!PointToLineCovariance::fixesEveryDirection(A - invented, invented))
		return std::numeric_limits<double>::infinity();
	const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(A - invented);
	const Eigen::Matrix3d others = eig.eigenvectors() *
		eig.eigenvalues().cwiseInverse().asDiagonal() * eig.eigenvectors().transpose();
	// The group's points (as paired at x) at that estimate, against their
	// covariance over sigma^2: their own noise, their circles' fits (de/d(ox,
	// oy, r) = (-n, -1) moves a circle's points together) and the others'
	// estimate.
	const auto m = static_cast<Eigen::Index>(end - first);
	Eigen::MatrixXd G(m, 3);
	Eigen::VectorXd e(m);
	for (Eigen::Index r = 0; r < m; r++)
	{
		Eigen::Vector3d g;
		e[r] = PointToLineCovariance::residual(
			xk, c, s, current, reference, m_lines[m_looOrder[first + static_cast<size_t>(r)].second], &g);
		G.row(r) = g.transpose();
	}
	Eigen::MatrixXd C = Eigen::MatrixXd::Identity(m, m) + G * others * G.transpose();
	for (Eigen::Index r = 0; r < m; r++)
		for (Eigen::Index q = 0; q < m; q++)
		{
			const int32_t kr = m_lines[m_looOrder[first + static_cast<size_t>(r)].second].round;
			if (kr != m_lines[m_looOrder[first + static_cast<size_t>(q)].second].round) continue;
			const Eigen::Vector3d ar(-G(r, 0), -G(r, 1), -1), aq(-G(q, 0), -G(q, 1), -1);
			C(r, q) += ar.dot(reference.roundThing(kr).circle.normalInverse * aq);
		}
	const double sigma2 = mrpt::square(std::max(1e-3, reference.rangeNoise()));
	const double chi2 = e.dot(C.ldlt().solve(e)) / sigma2;
	return chi2 / mrpt::math::chi2inv(0.999, static_cast<unsigned int>(m));
}

bool IterativeDualCorrespondence::dropMovedRoundThing(
	const ReferencePolyline& reference, const std::vector<ScanPoint>& current,
	const mrpt::math::TPose2D& x, double D)
{
	if (m_lines.size() < 3 ||
		std::none_of(m_lines.begin(), m_lines.end(), [](const PointToLinePair& pr) { return pr.round >= 0; }))
		return false;
	const double c = std::cos(x.phi), s = std::sin(x.phi);
	// The information of every pair at x (pointToLineStep's normal
	// equations) with what noisy normals invent (PointToLineCovariance),
	// and the round things' pairs.
	const size_t n = m_lines.size();
	m_looGradients.resize(n);
	m_looInvented.resize(n);
	Eigen::Matrix3d A = Eigen::Matrix3d::Zero(), invented = Eigen::Matrix3d::Zero();
	m_looOrder.clear();
	for (size_t j = 0; j < n; j++)
	{
		const PointToLinePair& pr = m_lines[j];
		Eigen::Vector3d& g = m_looGradients[j];
		PointToLineCovariance::residual(x, c, s, current, reference, pr, &g);
		m_looInvented[j] = PointToLineCovariance::inventedInformation(x, c, s, current, reference, pr, g);
		A += g * g.transpose();
		invented += m_looInvented[j];
		if (pr.round >= 0) m_looOrder.emplace_back(pr.round, static_cast<uint32_t>(j));
	}
	// Round things whose centres lie within kRoundGroupDistance of each
	// other are one group (a person's two legs, people side by side):
	// they may move together, so they are tested together. Labels by
	// union of the circles, in m_looGroup.
	const size_t nc = reference.roundThings();
	m_looGroup.resize(nc);
	for (size_t k = 0; k < nc; k++) m_looGroup[k] = static_cast<int32_t>(k);
	auto root = [&](int32_t k) {
		while (m_looGroup[static_cast<size_t>(k)] != k)
			k = m_looGroup[static_cast<size_t>(k)] =
				m_looGroup[static_cast<size_t>(m_looGroup[static_cast<size_t>(k)])];
		return k;
	};
	for (size_t k = 0; k < nc; k++)
		for (size_t l = k + 1; l < nc; l++)
		{
			const CircleFit &ck = reference.roundThing(static_cast<int32_t>(k)).circle,
							&cl = reference.roundThing(static_cast<int32_t>(l)).circle;
			if (std::hypot(ck.ox - cl.ox, ck.oy - cl.oy) < kRoundGroupDistance)
				m_looGroup[static_cast<size_t>(root(static_cast<int32_t>(k)))] =
					root(static_cast<int32_t>(l));
		}
	for (size_t k = 0; k < nc; k++) m_looGroup[k] = root(static_cast<int32_t>(k));
	for (auto& pr : m_looOrder) pr.first = m_looGroup[static_cast<size_t>(pr.first)];
	std::sort(m_looOrder.begin(), m_looOrder.end());
	int32_t worst = -1;
	double worstRatio = 1;
	for (size_t i = 0; i < m_looOrder.size();)
	{
		size_t end = i;
		while (end < m_looOrder.size() && m_looOrder[end].first == m_looOrder[i].first) end++;
		const int32_t group = m_looOrder[i].first;
		Eigen::Matrix3d Ak = Eigen::Matrix3d::Zero(), inventedK = Eigen::Matrix3d::Zero();
		for (size_t r = i; r < end; r++)
		{
			const uint32_t j = m_looOrder[r].second;
			Ak += m_looGradients[j] * m_looGradients[j].transpose();
			inventedK += m_looInvented[j];
		}
		// Without the group, do the others still fix every direction of
		// the motion (beyond PointToLineCovariance::kInventedMargin times
		// what noisy normals invent), and know each at least
		// 1 / kRoundShareOfInformation as well as the group does (the
		// largest generalised eigenvalue of its information against
		// theirs)? If not (a person walking along a corridor whose walls
		// fix little along it), the estimate follows the group, its
		// residuals stay small and nothing can tell a thing that moved
		// from one that stood still: it is dropped. (A trunk among the
		// orchard's dozens carries a small share.)
		const Eigen::Matrix3d rest = A - Ak - (invented - inventedK);
		const bool restFixes = PointToLineCovariance::fixesEveryDirection(rest, invented - inventedK);
		bool alone = !restFixes && PointToLineCovariance::fixesEveryDirection(A - invented, invented);
		if (restFixes)
		{
			const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix3d> share(
				Ak - inventedK, rest, Eigen::EigenvaluesOnly);
			alone = !(share.eigenvalues().maxCoeff() <= kRoundShareOfInformation);
		}
		double ratio;
		if (alone)
			ratio = std::numeric_limits<double>::infinity();
		else
			ratio = leftOutGroupRatio(reference, current, x, D, i, end, group);
		if (!(ratio <= worstRatio))
		{
			worstRatio = ratio;
			worst = group;
		}
		i = end;
	}
	if (worst < 0) return false;
	for (size_t k = 0; k < nc; k++)
		if (m_looGroup[k] == worst) m_roundDropped[k] = 1;
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
	m_roundDropped.assign(reference.roundThings(), 0);
	mrpt::math::TPose2D pointToLineStart = x;
	auto settled = [&] {
		// A round thing that the rest of the scan says has moved, or that
		// alone fixes a direction, is dropped, and the point-to-line phase
		// starts again without it from where it started (with these point
		// sets): where the thing pulled the estimate, the lines may hold it
		// (a corridor's walls along the corridor).
		if (!dual && dropMovedRoundThing(reference, current, x, D))
		{
			x = pointToLineStart;
			previousErrors.fill(-1);
			m_closestHint.assign(current.size(), ReferencePolyline::kNoHint);
			return false;
		}
		if (!dual && onConverged && !refined)
		{
			refined = true;
			if (onConverged(x))
			{
				// New point sets: their round things are tested afresh, and
				// a drop restarts from here.
				m_roundDropped.assign(reference.roundThings(), 0);
				pointToLineStart = x;
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
			pointToLineStart = x;
			previousErrors.fill(-1);
			if (onPointToLine)
			{
				// The caller may change both point sets here.
				onPointToLine(x);
				m_closestHint.assign(current.size(), ReferencePolyline::kNoHint);
				m_roundDropped.assign(reference.roundThings(), 0);
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
				PointToLinePair pair;
				double distance;
				if (pointToLinePair(reference, hit, static_cast<uint32_t>(i), qx, qy, m_roundDropped,
						pair, distance))
				{
					m_lines.push_back(pair);
					m_lineDistances.push_back(distance);
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
			if (!pointToLineStep(reference, current, m_lines, x, stepSigmas))
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
			r.rangeSigma, H, params.covariance_residual_span))
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
