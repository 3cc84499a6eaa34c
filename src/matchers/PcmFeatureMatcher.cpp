#include "featloc/matchers/PcmFeatureMatcher.h"

#include <mrpt/math/wrap2pi.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "featloc/config/ConfigValues.h"
#include "featloc/matchers/MotionConstraintCheck.h"

namespace featloc
{
IMPLEMENTS_MRPT_OBJECT(PcmFeatureMatcher, ScanMatcher, featloc)

namespace
{
/** Memberships below this are left out of the sums (exp(-d^2/eta) < 1e-9
 * means d > 4.5 d_max). */
constexpr double kMinMembership = 1e-9;

std::vector<double> boundsToFile(const std::vector<double>& b)
{
	return {b[0], b[1], mrpt::RAD2DEG(b[2])};
}

Eigen::Matrix2d rotation(double w)
{
	Eigen::Matrix2d R;
	R << std::cos(w), std::sin(w), -std::sin(w), std::cos(w);	// eq. (2)
	return R;
}

/** Covariance of a feature's own parameters: (rho, alpha) for a line,
 * f for an ellipse. */
Eigen::Matrix2d parameterCovariance(const ScanFeature& f)
{
	Eigen::Matrix2d C;
	if (f.kind == ScanFeature::Kind::Line)
		C << f.varRho, f.covRhoAlpha, f.covRhoAlpha, f.varAlpha;
	else
		C << f.cxx, f.cxy, f.cxy, f.cyy;
	return C;
}

/** Everything about one pair at a motion x: the residual
 * r = f_j - R(w)(f_i - A_i t) (eq. 12), its Jacobian H in (t, w), the
 * Jacobian G of the prediction in the reference feature's parameters, and
 * the residual's covariance C from both features' covariances. A line's
 * prediction is R (rho - n.t) n, so with u = dn/dalpha,
 * G = R [n, (rho - n.t) u - (u.t) n] (A depends on alpha too); an
 * ellipse's is R. */
struct PairTerms
{
	Eigen::Vector2d r;
	Eigen::Matrix<double, 2, 3> H;
	Eigen::Matrix2d G, C;

	PairTerms(const ScanFeature& fi, const ScanFeature& fj, const mrpt::math::TPose2D& x)
	{
		const Eigen::Matrix2d R = rotation(x.phi);
		Eigen::Matrix2d dR;	 // dR/dw
		dR << -std::sin(x.phi), std::cos(x.phi), -std::cos(x.phi), -std::sin(x.phi);
		Eigen::Matrix2d A;
		A << fi.a2, fi.c, fi.c, fi.b2;
		const Eigen::Vector2d t(x.x, x.y);
		const Eigen::Vector2d v = Eigen::Vector2d(fi.x, fi.y) - A * t;
		r = Eigen::Vector2d(fj.x, fj.y) - R * v;
		H.leftCols<2>() = R * A;
		H.col(2) = -dR * v;
		if (fi.kind == ScanFeature::Kind::Line)
		{
			const Eigen::Vector2d n(std::cos(fi.alpha), std::sin(fi.alpha));
			const Eigen::Vector2d u(-n[1], n[0]);
			G.col(0) = R * n;
			G.col(1) = R * ((fi.rho - n.dot(t)) * u - u.dot(t) * n);
		}
		else
			G = R;
		Eigen::Matrix2d Cj;
		Cj << fj.cxx, fj.cxy, fj.cxy, fj.cyy;
		C = Cj + G * parameterCovariance(fi) * G.transpose();
	}
};
}  // namespace

void PcmFeatureMatcher::Parameters::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	using namespace featloc::config;
	extraction.loadFromConfigFile(c, s);
	read(c, s, "max_iterations", max_iterations);
	read(c, s, "bound_iterations", bound_iterations);
	for (auto* b : {&final_bounds, &initial_bounds})
	{
		const std::string key = b == &final_bounds ? "final_bounds" : "initial_bounds";
		std::vector<double> v = boundsToFile(*b);
		read(c, s, key, v);
		require(v.size() == 3 && v[0] > 0 && v[1] > 0 && v[2] > 0, c, s, key,
			"three positive numbers [x_m y_m yaw_deg]");
		*b = {v[0], v[1], mrpt::DEG2RAD(v[2])};
	}
	readChoice(c, s, "initial_bounds_source", initial_bounds_source, {"covariance", "config"});
	read(c, s, "bounds_sigmas", bounds_sigmas);
	read(c, s, "stop_translation", stop_translation);
	readDegrees(c, s, "stop_rotation_DEG", stop_rotation);
	readChoice(c, s, "refinement", refinement, {"weighted", "none"});
	read(c, s, "pair_gate_chi2", pair_gate_chi2);
	readChoice(c, s, "dmax_corners", dmax_corners, {"all", "published"});
	read(c, s, "motion_window_bounds", motion_window_bounds);
	require(motion_window_bounds >= 0, c, s, "motion_window_bounds", ">= 0 (0: no window)");
	read(c, s, "guess_gate_chi2", guess_gate_chi2);
	require(guess_gate_chi2 >= 0, c, s, "guess_gate_chi2", ">= 0 (0 disables it)");
	read(c, s, "min_matched_features", min_matched_features);
	read(c, s, "max_translation_sigma", max_translation_sigma);
	readDegrees(c, s, "max_rotation_sigma_DEG", max_rotation_sigma);
	require(max_iterations >= 1, c, s, "max_iterations", ">= 1");
	require(bound_iterations >= 1 && bound_iterations <= max_iterations, c, s,
		"bound_iterations", "in [1, max_iterations]");
	require(bounds_sigmas > 0, c, s, "bounds_sigmas", "> 0");
	require(stop_translation >= 0, c, s, "stop_translation", ">= 0");
	require(stop_rotation >= 0, c, s, "stop_rotation_DEG", ">= 0");
	require(pair_gate_chi2 >= 0, c, s, "pair_gate_chi2", ">= 0 (0 disables the gate)");
	require(min_matched_features >= 1, c, s, "min_matched_features", ">= 1");
	require(max_translation_sigma > 0, c, s, "max_translation_sigma", "> 0");
	require(max_rotation_sigma > 0, c, s, "max_rotation_sigma_DEG", "> 0");
}

void PcmFeatureMatcher::Parameters::saveToConfigFile(
	mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	using namespace featloc::config;
	extraction.saveToConfigFile(c, s);
	write(c, s, "max_iterations", max_iterations, "n_max: iterations at most");
	write(c, s, "bound_iterations", bound_iterations,
		"n_s: the motion bounds shrink during this many iterations (eq. 26)");
	write(c, s, "final_bounds", boundsToFile(final_bounds),
		"[m m deg] Delta_{n_s}: bounds after shrinking");
	write(c, s, "initial_bounds_source", initial_bounds_source,
		"covariance (bounds_sigmas of the guess) | config (initial_bounds)");
	write(c, s, "initial_bounds", boundsToFile(initial_bounds),
		"[m m deg] Delta_0 when initial_bounds_source = config");
	write(c, s, "bounds_sigmas", bounds_sigmas,
		"Delta_0 = this many standard deviations of the guess");
	write(c, s, "stop_translation", stop_translation, "[m] epsilon_t of the stop test");
	writeDegrees(c, s, "stop_rotation_DEG", stop_rotation, "[deg] epsilon_w of the stop test");
	write(c, s, "refinement", refinement,
		"weighted (covariance-weighted final step) | none (the paper's estimate)");
	write(c, s, "pair_gate_chi2", pair_gate_chi2,
		"drop pairs whose residual's Mahalanobis^2 exceeds this, re-solve (0 = off)");
	write(c, s, "dmax_corners", dmax_corners,
		"d_max of eq. (24): all (the largest over the 8 corners of the motion bounds) | "
		"published (the one corner t + Delta_t, w + Delta_w the paper writes)");
	write(c, s, "motion_window_bounds", motion_window_bounds,
		"the estimate stays within this many Delta_0 of the guess: rotation candidates "
		"outside are dropped, an estimate outside fails (0: neither, as published)");
	write(c, s, "guess_gate_chi2", guess_gate_chi2,
		"failure when the estimate's Mahalanobis^2 from the initial guess exceeds this "
		"(21.1: 99.99% for 3 dof; 0 = off, as published)");
	write(c, s, "min_matched_features", min_matched_features,
		"failure below this many matched current features");
	write(c, s, "max_translation_sigma", max_translation_sigma,
		"[m] failure when the estimate's sigma along some direction exceeds this");
	writeDegrees(c, s, "max_rotation_sigma_DEG", max_rotation_sigma,
		"[deg] failure when the estimate's rotation sigma exceeds this");
}

void PcmFeatureMatcher::loadOwnParams(
	const mrpt::config::CConfigFileBase& cfg, const std::string& section)
{
	params.loadFromConfigFile(cfg, section);
	m_extractor.params = params.extraction;
}

void PcmFeatureMatcher::saveOwnParams(
	mrpt::config::CConfigFileBase& cfg, const std::string& section) const
{
	params.saveToConfigFile(cfg, section);
}

void PcmFeatureMatcher::memberships(const mrpt::math::TPose2D& x, const double bounds[3])
{
	m_pairs.clear();
	// The rotations of the bounds box's corners and of its centre (sw = 0),
	// for every feature.
	double cosW[3], sinW[3];
	for (int sw = -1; sw <= 1; sw++)
	{
		cosW[sw + 1] = std::cos(x.phi + sw * bounds[2]);
		sinW[sw + 1] = std::sin(x.phi + sw * bounds[2]);
	}
	for (size_t i = 0; i < m_reference.size(); i++)
	{
		const ScanFeature& fi = m_reference[i];
		double px = 0, py = 0;
		PcmMotionUpdate::predict(fi, x, cosW[1], sinW[1], px, py);
		// Eq. (24): the paper's one corner of the bounds box, or featloc's
		// largest over all eight (the maximum need not be at that corner).
		double dmax2 = 0;
		auto corner = [&](int sx, int sy, int sw) {
			double cx = 0, cy = 0;
			PcmMotionUpdate::predict(fi,
				{x.x + sx * bounds[0], x.y + sy * bounds[1], x.phi + sw * bounds[2]},
				cosW[sw + 1], sinW[sw + 1], cx, cy);
			dmax2 = std::max(dmax2, (cx - px) * (cx - px) + (cy - py) * (cy - py));
		};
		if (params.dmax_corners == "published")
			corner(1, 1, 1);
		else
			for (int sx : {-1, 1})
				for (int sy : {-1, 1})
					for (int sw : {-1, 1}) corner(sx, sy, sw);
		const double eta = std::max(dmax2 / std::log(2.0), 1e-12);	// eq. (25)
		for (size_t j = 0; j < m_current.size(); j++)
		{
			const ScanFeature& fj = m_current[j];
			if (fj.kind != fi.kind) continue;  // no line-ellipse pairs
			const double dx = fj.x - px, dy = fj.y - py;
			const double mu = std::exp(-(dx * dx + dy * dy) / eta);	// eq. (14)
			if (mu > kMinMembership)
				m_pairs.push_back({static_cast<uint32_t>(i), static_cast<uint32_t>(j), mu});
		}
	}
}

mrpt::math::TPose2D PcmFeatureMatcher::refine(const mrpt::math::TPose2D& start) const
{
	// Gauss-Newton on sum mu r^T C^-1 r, the pairs fixed.
	mrpt::math::TPose2D x = start;
	for (int it = 0; it < 5; it++)
	{
		Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
		Eigen::Vector3d b = Eigen::Vector3d::Zero();
		for (const auto& p : m_pairs)
		{
			const PairTerms k(m_reference[p.i], m_current[p.j], x);
			const Eigen::Matrix<double, 3, 2> HtW = k.H.transpose() * k.C.inverse();
			A += p.mu * HtW * k.H;
			b += p.mu * HtW * k.r;
		}
		// A little damping keeps unconstrained directions (a corridor) where
		// they are; the degeneracy check reports them.
		A.diagonal().array() += 1e-9 * (1 + A.trace());
		const Eigen::Vector3d step = -A.ldlt().solve(b);
		if (!step.allFinite()) break;
		x = {x.x + step[0], x.y + step[1], mrpt::math::wrapToPi(x.phi + step[2])};
		if (std::hypot(step[0], step[1]) < 1e-9 && std::abs(step[2]) < 1e-10) break;
	}
	return x;
}

bool PcmFeatureMatcher::covariance(
	const mrpt::math::TPose2D& x, mrpt::math::CMatrixDouble33& cov,
	std::string& reason) const
{
	// The estimate solves g = sum mu H^T W r = 0 (W = I for the paper's
	// estimator, C^-1 after the weighted refinement): its covariance is the
	// sandwich B^-1 S B^-1, B = sum mu H^T W H. A feature's noise enters
	// every pair it is in (a wall cut by an occluder gives several features,
	// all paired with each other), so S is summed per feature:
	// S = sum_j K_j C_fj K_j^T + sum_i L_i C_i L_i^T,
	// K_j = sum_i mu H^T W, L_i = sum_j mu H^T W G.
	const bool weighted = params.refinement == "weighted";
	Eigen::Matrix3d B = Eigen::Matrix3d::Zero();
	m_perCurrent.assign(m_current.size(), Eigen::Matrix<double, 3, 2>::Zero());
	m_perReference.assign(m_reference.size(), Eigen::Matrix<double, 3, 2>::Zero());
	for (const auto& p : m_pairs)
	{
		const PairTerms k(m_reference[p.i], m_current[p.j], x);
		const Eigen::Matrix<double, 3, 2> HtW =
			weighted ? Eigen::Matrix<double, 3, 2>(k.H.transpose() * k.C.inverse())
					 : Eigen::Matrix<double, 3, 2>(k.H.transpose());
		B += p.mu * HtW * k.H;
		m_perCurrent[p.j] += p.mu * HtW;
		m_perReference[p.i] += p.mu * HtW * k.G;
	}
	// Numerically singular: a direction with (almost) no information.
	const MotionConstraintCheck check(params.max_translation_sigma, params.max_rotation_sigma,
		"the matched features", "all matched lines parallel to it, as in a corridor");
	reason = check.singular(B);
	if (!reason.empty()) return false;
	Eigen::Matrix3d S = Eigen::Matrix3d::Zero();
	for (size_t j = 0; j < m_current.size(); j++)
	{
		const ScanFeature& f = m_current[j];
		Eigen::Matrix2d C;
		C << f.cxx, f.cxy, f.cxy, f.cyy;
		S += m_perCurrent[j] * C * m_perCurrent[j].transpose();
	}
	for (size_t i = 0; i < m_reference.size(); i++)
		S += m_perReference[i] * parameterCovariance(m_reference[i]) *
			m_perReference[i].transpose();
	const Eigen::Matrix3d Binv = B.inverse();
	const Eigen::Matrix3d C = Binv * S * Binv;
	for (int r = 0; r < 3; r++)
		for (int c = 0; c < 3; c++) cov(r, c) = 0.5 * (C(r, c) + C(c, r));

	// Weakly constrained: the estimate is too uncertain along some
	// direction to be of use.
	reason = check.tooUncertain(C);
	return reason.empty();
}

size_t PcmFeatureMatcher::gate(
	const mrpt::math::TPose2D& x, const mrpt::math::CMatrixDouble33& cov)
{
	const auto before = m_pairs.size();
	const Eigen::Matrix3d P = cov.asEigen();
	m_pairs.erase(
		std::remove_if(m_pairs.begin(), m_pairs.end(),
			[&](const FeaturePair& p) {
				const PairTerms k(m_reference[p.i], m_current[p.j], x);
				// The residual at the estimate varies with the features and
				// with the estimate itself: C + H P H^T (conservative).
				const Eigen::Matrix2d V = k.C + k.H * P * k.H.transpose();
				return k.r.dot(V.ldlt().solve(k.r)) > params.pair_gate_chi2;
			}),
		m_pairs.end());
	return before - m_pairs.size();
}

void PcmFeatureMatcher::matchPoints(
	const ScanPoints& reference, const ScanPoints& current,
	const mrpt::poses::CPosePDFGaussian& initialGuess, MatchResult& result)
{
	m_extractor.params = params.extraction;
	m_extractor.rangeNoiseFloor = rangeLatticeCellSigma();
	m_extractor.extract(reference, m_reference);
	m_extractor.extract(current, m_current);
	result.success = false;
	result.iterations = 0;
	if (m_reference.empty() || m_current.empty())
	{
		result.failureReason = "no features extracted (reference " +
			std::to_string(m_reference.size()) + ", current " +
			std::to_string(m_current.size()) + ")";
		return;
	}

	// Motion bounds: Delta_0 and tau per component (eq. 26).
	double delta0[3], tau[3];
	for (int k = 0; k < 3; k++)
	{
		delta0[k] = params.initial_bounds_source == "config"
			? params.initial_bounds[k]
			: params.bounds_sigmas * std::sqrt(std::max(0.0, initialGuess.cov(k, k)));
		delta0[k] = std::max(delta0[k], params.final_bounds[k]);
		const double ratio = delta0[k] / params.final_bounds[k];
		tau[k] = ratio > 1 ? params.bound_iterations / std::log(ratio) : 0;
	}
	auto boundsAt = [&](unsigned n, double out[3]) {
		const double m = std::min(n, params.bound_iterations);
		for (int k = 0; k < 3; k++)
			out[k] = tau[k] > 0 ? delta0[k] * std::exp(-m / tau[k]) : delta0[k];
	};

	// Section 4, steps 2-7.
	const mrpt::math::TPose2D guess = initialGuess.mean.asTPose();
	mrpt::math::TPose2D x = guess;
	double bounds[3];
	unsigned n = 0;
	while (true)
	{
		boundsAt(n, bounds);
		memberships(x, bounds);	 // steps 2-4
		n++;  // step 5
		if (m_pairs.empty()) break;
		const mrpt::math::TPose2D next = PcmMotionUpdate::solve(
			m_reference, m_current, m_pairs, x, 1e-9, guess.phi,
			params.motion_window_bounds * delta0[2]);	 // step 6
		const double dt = std::hypot(next.x - x.x, next.y - x.y);
		const double dw = std::abs(mrpt::math::wrapToPi(next.phi - x.phi));
		x = next;
		if ((dt <= params.stop_translation && dw <= params.stop_rotation) ||
			n >= params.max_iterations)	 // step 7
			break;
	}
	result.iterations = n;
	boundsAt(n, bounds);
	memberships(x, bounds);

	// Final estimate on the converged pairs, the consistency gate, and the
	// covariance of the estimator actually used.
	auto estimate = [&] {
		if (params.refinement == "weighted")
			x = refine(x);
		else
			x = PcmMotionUpdate::solve(m_reference, m_current, m_pairs, x, 1e-9,
				guess.phi, params.motion_window_bounds * delta0[2]);
	};
	if (!m_pairs.empty()) estimate();
	std::string reason;
	bool ok = !m_pairs.empty() && covariance(x, result.estimate.cov, reason);
	for (int pass = 0; ok && pass < 3 && params.pair_gate_chi2 > 0; pass++)
	{
		if (gate(x, result.estimate.cov) == 0 || m_pairs.empty()) break;
		estimate();
		ok = covariance(x, result.estimate.cov, reason);
	}
	result.estimate.mean = mrpt::poses::CPose2D(x);

	// Matched current features: those with a strong membership.
	std::vector<double> best(m_current.size(), 0.0);
	for (const auto& p : m_pairs) best[p.j] = std::max(best[p.j], p.mu);
	const size_t matched =
		static_cast<size_t>(std::count_if(best.begin(), best.end(), [](double m) { return m > 0.5; }));
	result.goodness = static_cast<double>(matched) / static_cast<double>(m_current.size());
	if (matched < params.min_matched_features)
	{
		result.failureReason = "only " + std::to_string(matched) + " of " +
			std::to_string(m_current.size()) +
			" current features matched (min_matched_features " +
			std::to_string(params.min_matched_features) + ")";
		return;
	}
	if (!ok)
	{
		result.failureReason = reason;
		return;
	}
	// The method assumes the motion lies within the bounds around the
	// initial estimate: an estimate far outside them is a wrong match.
	const double off[3] = {std::abs(x.x - guess.x), std::abs(x.y - guess.y),
		std::abs(mrpt::math::wrapToPi(x.phi - guess.phi))};
	const double window = params.motion_window_bounds;
	for (int k = 0; k < 3 && window > 0; k++)
		if (off[k] > window * delta0[k])
		{
			char buf[160];
			std::snprintf(buf, sizeof(buf),
				"the estimate left the motion bounds (moved %.3f %s from the "
				"initial guess in %s, bound %.3f)",
				k == 2 ? mrpt::RAD2DEG(off[k]) : off[k], k == 2 ? "deg" : "m",
				k == 0 ? "x" : (k == 1 ? "y" : "rotation"),
				k == 2 ? mrpt::RAD2DEG(window * delta0[k]) : window * delta0[k]);
			result.failureReason = buf;
			return;
		}
	result.success = true;
}
MatchInspection PcmFeatureMatcher::inspectOwnMatch(const ScanPoints& reference,
	const ScanPoints& current, const mrpt::poses::CPose2D&) const
{
	// The features of both scans and the pairs of the last PCM iteration,
	// centre to centre, with their membership mu_ij (section 4, eq. 15).
	MatchInspection out;
	out.pairsDescription = "PCM feature pairs of the last iteration (centre to centre)";
	auto addParts = [&](const std::vector<ScanFeature>& features, const ScanPoints& scan,
						bool isCurrent) {
		for (size_t k = 0; k < features.size(); k++)
		{
			const ScanFeature& f = features[k];
			MatchInspection::Part part;
			part.current = isCurrent;
			part.kind = f.kind == ScanFeature::Kind::Line ? "line" : "ellipse";
			for (uint32_t i = f.firstPoint; i <= f.lastPoint && i < scan.size(); i++)
			{
				part.points.push_back({scan.points[i].x, scan.points[i].y});
				part.beams.push_back(scan.points[i].beam);
			}
			double bestMu = 0;
			for (const auto& p : m_pairs)
				if ((isCurrent ? p.j : p.i) == k) bestMu = std::max(bestMu, p.mu);
			part.kept = bestMu > 0;
			char note[96];
			std::snprintf(note, sizeof(note), "%s %zu, %.2f m, best mu %.2f", part.kind.c_str(), k,
				f.length, bestMu);
			part.note = bestMu > 0 ? note : std::string(note) + " (unpaired)";
			out.parts.push_back(std::move(part));
		}
	};
	addParts(m_reference, reference, false);
	addParts(m_current, current, true);
	for (const auto& p : m_pairs)
		if (p.i < m_reference.size() && p.j < m_current.size())
			out.pairs.push_back({{m_reference[p.i].x, m_reference[p.i].y},
				{m_current[p.j].x, m_current[p.j].y}});
	return out;
}
}  // namespace featloc
