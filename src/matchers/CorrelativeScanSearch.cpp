#include "featloc/matchers/CorrelativeScanSearch.h"

#include <mrpt/core/bits_math.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <opencv2/imgproc.hpp>

#include "featloc/config/ConfigValues.h"
#include "featloc/math/PoseDifference.h"
#include "featloc/scan/AdaptiveBreakpointSegmenter.h"

namespace featloc
{
namespace
{
/** The tables never exceed this many cells: a reference spread wider than
 * resolution x 1500 cells per side is searched at a coarser resolution. */
constexpr double kMaxTableCells = 1500.0 * 1500.0;
/** The tables hold distances up to this many widths of the wider score
 * (CorrelationTables::buildNear): the featloc-bench --pairs files of the
 * office and edmonton are byte-identical to the exact transform's. */
constexpr double kNearSigmas = 5.0;

/** The breakpoint rule that joins reference points into surfaces: lambda
 * (the most grazing incidence still one surface) and the range noise. */
constexpr double kJoinLambda = 0.08726646259971647;	 //!< [rad] (5 deg)
constexpr double kJoinSigmaR = 0.01;  //!< [m]
/** The sharp score's sigma is at least this many times the reference
 * scan's own point scatter (PointNoiseEstimator). */
constexpr double kSharpNoiseFactor = 2.0;

/** Contenders outside the guess's 99% region (chi2, 3 dof) are ignored. */
constexpr double kPlausibleChi2 = 11.34;
/** At most this many contenders are refined and compared with the estimate. */
constexpr size_t kMaxContenders = 6;

/** Squared Mahalanobis distance of `pose` from the guess (Pinv its inverse
 * covariance); 0 when the guess's covariance has no finite inverse (no
 * prior). */
double guessMahalanobis2(
	const mrpt::poses::CPose2D& pose, const mrpt::poses::CPose2D& mean, const Eigen::Matrix3d& Pinv)
{
	if (!Pinv.allFinite()) return 0;
	const Eigen::Vector3d d = poseDifference(pose, mean);
	return d.dot(Pinv * d);
}

double mean(const std::vector<double>& v)
{
	double sum = 0;
	for (double x : v) sum += x;
	return v.empty() ? 0.0 : sum / static_cast<double>(v.size());
}
}  // namespace

void CorrelativeScanSearch::Options::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	using namespace featloc::config;
	read(c, s, "coarse_search", enabled);
	read(c, s, "coarse_window_sigmas", windowSigmas);
	read(c, s, "coarse_min_window_xy", minWindowXY);
	readDegrees(c, s, "coarse_min_window_yaw_DEG", minWindowYaw);
	read(c, s, "coarse_max_window_xy", maxWindowXY);
	readDegrees(c, s, "coarse_max_window_yaw_DEG", maxWindowYaw);
	read(c, s, "coarse_resolution", resolution);
	read(c, s, "coarse_hit_sigma", hitSigma);
	read(c, s, "coarse_max_points", maxPoints);
	read(c, s, "coarse_min_score", minScore);
	read(c, s, "coarse_contender_ratio", contenderRatio);
	read(c, s, "coarse_ambiguity_z", ambiguityZ);
	read(c, s, "coarse_overrule_guess_z", overruleGuessZ);
	read(c, s, "coarse_overrule_object_span", overruleObjectSpan);
	read(c, s, "coarse_sharp_sigma", sharpSigma);
	readChoice(c, s, "coarse_on_ambiguity", onAmbiguity, {"inflate", "fail"});
	read(c, s, "coarse_distinct_xy", distinctXY);
	readDegrees(c, s, "coarse_distinct_yaw_DEG", distinctYaw);
	read(c, s, "coarse_refine_rivals", refineRivals);
	read(c, s, "coarse_confirm_share", confirmShare);
	read(c, s, "coarse_confirm_distance", confirmDistance);
	read(c, s, "coarse_confirm_probe", confirmProbe);
	read(c, s, "coarse_confirm_probe_window", confirmProbeWindow);
	read(c, s, "coarse_confirm_probe_sigma", confirmProbeSigma);
	read(c, s, "coarse_confirm_probe_turn", confirmProbeTurn);
	require(windowSigmas > 0, c, s, "coarse_window_sigmas", "> 0");
	require(minWindowXY >= 0, c, s, "coarse_min_window_xy", ">= 0");
	require(minWindowYaw >= 0, c, s, "coarse_min_window_yaw_DEG", ">= 0");
	require(maxWindowXY >= minWindowXY && maxWindowXY <= 5, c, s, "coarse_max_window_xy",
		"in [coarse_min_window_xy, 5]");
	require(maxWindowYaw >= minWindowYaw && maxWindowYaw <= M_PI, c, s,
		"coarse_max_window_yaw_DEG", "in [coarse_min_window_yaw_DEG, 180]");
	require(resolution >= 0.005 && resolution <= 0.5, c, s, "coarse_resolution",
		"in [0.005, 0.5]");
	require(hitSigma > 0, c, s, "coarse_hit_sigma", "> 0");
	require(maxPoints >= 3, c, s, "coarse_max_points", ">= 3");
	require(minScore >= 0 && minScore <= 1, c, s, "coarse_min_score", "in [0, 1]");
	require(ambiguityZ >= 0, c, s, "coarse_ambiguity_z", ">= 0 (0 disables the check)");
	require(contenderRatio > 0 && contenderRatio <= 1, c, s, "coarse_contender_ratio", "in (0, 1]");
	require(overruleGuessZ >= 0, c, s, "coarse_overrule_guess_z", ">= 0 (0 disables it)");
	require(overruleObjectSpan >= 0 && overruleObjectSpan <= 10, c, s,
		"coarse_overrule_object_span", "in [0, 10] (0: every point is a witness)");
	require(sharpSigma > 0, c, s, "coarse_sharp_sigma", "> 0");
	require(distinctXY > 0, c, s, "coarse_distinct_xy", "> 0");
	require(distinctYaw > 0, c, s, "coarse_distinct_yaw_DEG", "> 0");
	require(confirmShare >= 0 && confirmShare <= 1, c, s, "coarse_confirm_share",
		"in [0, 1] (0: the search always runs)");
	require(confirmDistance > 0, c, s, "coarse_confirm_distance", "> 0");
	require(confirmProbeSigma >= 0, c, s, "coarse_confirm_probe_sigma", ">= 0");
}

void CorrelativeScanSearch::Options::saveToConfigFile(
	mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	using namespace featloc::config;
	write(c, s, "coarse_search", enabled,
		"wide basin: correlative search of the guess's window before the iterations "
		"(Olson 2009; not in the paper)");
	write(c, s, "coarse_window_sigmas", windowSigmas,
		"half-window searched, in sigmas of the guess (gate allowance included)");
	write(c, s, "coarse_min_window_xy", minWindowXY, "[m] half-window at least this");
	writeDegrees(c, s, "coarse_min_window_yaw_DEG", minWindowYaw,
		"[deg] half-window at least this");
	write(c, s, "coarse_max_window_xy", maxWindowXY, "[m] half-window at most this");
	writeDegrees(c, s, "coarse_max_window_yaw_DEG", maxWindowYaw,
		"[deg] half-window at most this");
	write(c, s, "coarse_resolution", resolution,
		"[m] lookup cell and translation step (coarser if the reference is very wide)");
	write(c, s, "coarse_hit_sigma", hitSigma,
		"[m] a point this far from the reference scores exp(-1/2)");
	write(c, s, "coarse_max_points", maxPoints, "current points scored (evenly picked)");
	write(c, s, "coarse_min_score", minScore,
		"match fails if no pose puts this share of points on the reference [0-1]");
	write(c, s, "coarse_contender_ratio", contenderRatio,
		"poses scoring this x the search's best are contenders for the ambiguity check");
	write(c, s, "coarse_ambiguity_z", ambiguityZ,
		"match fails unless the points favour the estimate over every distinct contender "
		"by this z (paired, sharp scores; 0: off)");
	write(c, s, "coarse_on_ambiguity", onAmbiguity,
		"inflate (the covariance grows to cover every rival; the match is used, flagged) | "
		"fail (the match fails)");
	write(c, s, "coarse_overrule_guess_z", overruleGuessZ,
		"a guess-gate rejection stands unless a search of the widest window around the guess finds "
		"the estimate, unambiguous, and the scan's objects favour it over the guess by this z "
		"(0: the gate always decides)");
	write(c, s, "coarse_overrule_object_span", overruleObjectSpan,
		"[m] for that z the current points are grouped into runs within this span, each run one "
		"witness (a person's points are one; 0: every point is one)");
	write(c, s, "coarse_sharp_sigma", sharpSigma,
		"[m] width of the sharp score that compares the estimate with the contenders");
	write(c, s, "coarse_distinct_xy", distinctXY,
		"[m] solutions further apart than this (or coarse_distinct_yaw_DEG) are distinct");
	writeDegrees(c, s, "coarse_distinct_yaw_DEG", distinctYaw,
		"[deg] solutions turned further apart than this are distinct");
	write(c, s, "coarse_refine_rivals", refineRivals,
		"the matcher's iterations also run from each rival: one they bring back to the estimate "
		"(within coarse_distinct_*) is no ambiguity (off: on the real logs it unflagged wrong "
		"matches too)");
	write(c, s, "coarse_confirm_share", confirmShare,
		"skip the search when the iterations from the guess succeed and put this "
		"share of the current points within coarse_confirm_distance of the reference "
		"(0: the search always runs)");
	write(c, s, "coarse_confirm_distance", confirmDistance,
		"[m] a current point this close to a reference point is confirmed");
	write(c, s, "coarse_confirm_probe", confirmProbe,
		"the search runs also where a pose slid by 2 or 4 x coarse_confirm_distance along the "
		"estimate's least certain translation puts as large a share within it");
	write(c, s, "coarse_confirm_probe_window", confirmProbeWindow,
		"the probe also slides every coarse_confirm_distance out to the search window's edges");
	write(c, s, "coarse_confirm_probe_sigma", confirmProbeSigma,
		"[m] the probe runs where the estimate's largest translation sigma reaches this "
		"(0: wherever the share confirms)");
	write(c, s, "coarse_confirm_probe_turn", confirmProbeTurn,
		"the probe follows the estimate's least certain motion with its turn (yaw scaled by the "
		"points' RMS range), turning the pose about that motion's centre; false: translation "
		"only");
}

mrpt::math::CMatrixDouble33 CorrelativeScanSearch::Result::gridCovariance() const
{
	// The best pose is the grid pose nearest the peak: within half a step
	// of it; one step as one sigma leaves the refining matcher room.
	mrpt::math::CMatrixDouble33 c;
	c(0, 0) = c(1, 1) = resolution * resolution;
	c(2, 2) = yawStep * yawStep;
	return c;
}

void CorrelativeScanSearch::pickPoints(const ScanPoints& current)
{
	m_px.clear();
	m_py.clear();
	m_allX.clear();
	m_allY.clear();
	for (const auto& p : current.points)
	{
		m_allX.push_back(p.x);
		m_allY.push_back(p.y);
	}
	const size_t n = current.size();
	const size_t m = std::min<size_t>(n, options.maxPoints);
	for (size_t k = 0; k < m; k++)
	{
		const auto& p = current.points[k * n / m];
		m_px.push_back(p.x);
		m_py.push_back(p.y);
	}
}

void CorrelativeScanSearch::buildTables(const ScanPoints& reference, double halfWindowXY)
{
	double xmin = 1e300, ymin = 1e300, xmax = -1e300, ymax = -1e300;
	for (const auto& p : reference.points)
	{
		xmin = std::min(xmin, p.x);
		xmax = std::max(xmax, p.x);
		ymin = std::min(ymin, p.y);
		ymax = std::max(ymax, p.y);
	}
	const double margin = 3 * options.hitSigma;
	double res = options.resolution;
	const double spanX = xmax - xmin + 2 * margin, spanY = ymax - ymin + 2 * margin;
	if (spanX * spanY / (res * res) > kMaxTableCells)
		res = std::sqrt(spanX * spanY / kMaxTableCells);
	const int top = CorrelationTables::topLevelFor(halfWindowXY, res);
	// A keyframe is the reference of every scan until the next one: its
	// tables (about half the search's time on a 361-beam office scan) are
	// built once for all of them, and once for a matcher and its fallback.
	const ReferenceTables::BuildOptions tableOptions{
		options.resolution, options.hitSigma, options.sharpSigma};
	if (useTablesOf(reference, top, tableOptions)) return;
	ReferenceTables& built = *m_ref;
	// The low side also holds one top-level block: a block's bound reads up
	// to its side - 1 cells beyond the point's own cell.
	const double lowMargin = margin + static_cast<double>(1 << top) * res;
	const double x0 = xmin - lowMargin, y0 = ymin - lowMargin;
	const int width = static_cast<int>(std::ceil((xmax + margin - x0) / res)) + 1;
	const int height = static_cast<int>(std::ceil((ymax + margin - y0) / res)) + 1;

	// Consecutive points of one surface are joined, as Borges & Aldon's
	// adaptive breakpoint detector keeps them in one segment, down to a
	// grazing incidence of kJoinLambda. Isolated points (more grazing, or
	// thin objects) are left out: a current point scores best where it
	// falls on a reference *sample*, so with them "no motion" would beat the
	// true motion along a corridor's walls (the beams fall where they fell).
	AdaptiveBreakpointSegmenter::Parameters join;
	join.lambda = kJoinLambda;
	join.sigma_r = kJoinSigmaR;
	AdaptiveBreakpointSegmenter(join).segment(reference, built.segments);
	// The sharp score's width follows the scan's own scatter about its
	// surfaces: a current point and the (noisy) reference surface are
	// sqrt(2) s apart on average, and a score narrower than that would
	// judge solutions by their noise.
	built.sharpSigma = std::max(
		options.sharpSigma, kSharpNoiseFactor * m_noise.estimate(reference.points, built.segments));
	auto draw = [&](cv::Mat& surface) {
		auto pixel = [&](const ScanPoint& p) {
			return cv::Point(static_cast<int>((p.x - x0) / res), static_cast<int>((p.y - y0) / res));
		};
		for (const auto& seg : built.segments)
			for (uint32_t i = seg.first + 1; i <= seg.last; i++)
				cv::line(surface, pixel(reference.points[i - 1]), pixel(reference.points[i]),
					cv::Scalar(0), 1, cv::LINE_8);
	};
	// Distances beyond kNearSigmas of both scores' widths change neither
	// score (exp(-12.5) = 4e-6 of a hit) but cost an exact transform of
	// the whole table: a real log's scan spans millions of cells.
	built.tables.buildNear(width, height, x0, y0, res, options.hitSigma, top,
		kNearSigmas * std::max(options.hitSigma, built.sharpSigma), draw);
	built.setBuiltFor(reference, top, tableOptions);
}

bool CorrelativeScanSearch::useTablesOf(
	const ScanPoints& reference, int top, const ReferenceTables::BuildOptions& options)
{
	for (const auto& t : *m_pool)  // this search's own among them
		if (t->builtFor(reference, top, options))
		{
			m_ref = t;
			return true;
		}
	// To be built: this search's own tables unless another search holds
	// them too, else tables nobody holds, else new ones.
	if (!m_ref || m_ref.use_count() > 2)
	{
		m_ref.reset();
		for (const auto& t : *m_pool)
			if (t.use_count() == 1)
			{
				m_ref = t;
				break;
			}
		if (!m_ref)
		{
			m_ref = std::make_shared<ReferenceTables>();
			m_pool->push_back(m_ref);
		}
	}
	return false;
}

void CorrelativeScanSearch::shareTablesWith(CorrelativeScanSearch& other)
{
	if (other.m_pool == m_pool) return;
	// This search's tables join the other's pool.
	if (m_ref) other.m_pool->push_back(m_ref);
	m_pool = other.m_pool;
}

CorrelativeScanSearch::HalfWindow CorrelativeScanSearch::halfWindow(
	const mrpt::poses::CPosePDFGaussian& guess) const
{
	const auto& P = guess.cov;
	auto half = [&](double var, double lo, double hi) {
		const double h = options.windowSigmas * std::sqrt(std::max(var, 0.0));
		return std::isfinite(h) ? std::clamp(h, lo, hi) : hi;
	};
	HalfWindow h;
	h.xy[0] = half(P(0, 0), options.minWindowXY, options.maxWindowXY);
	h.xy[1] = half(P(1, 1), options.minWindowXY, options.maxWindowXY);
	h.yaw = half(P(2, 2), options.minWindowYaw, options.maxWindowYaw);
	return h;
}

CorrelativeScanSearch::Result CorrelativeScanSearch::search(
	const ScanPoints& reference, const ScanPoints& current,
	const mrpt::poses::CPosePDFGaussian& guess)
{
	Result r;
	r.best = guess.mean;
	if (reference.empty() || current.empty())
	{
		r.failureReason = "coarse search: an empty scan";
		return r;
	}
	const HalfWindow h = halfWindow(guess);
	r.windowXY[0] = h.xy[0];
	r.windowXY[1] = h.xy[1];
	r.windowYaw = h.yaw;
	buildTables(reference, std::max(r.windowXY[0], r.windowXY[1]));
	pickPoints(current);
	r.resolution = m_ref->tables.resolution();

	r.yawStep = CorrelationTables::rotationStep(m_px, m_py, r.resolution);
	const size_t n = m_px.size();

	const auto found = branchAndBound(guess, r);
	if (found.empty())
	{
		r.failureReason = "coarse search: no current point near the reference in the window";
		return r;
	}
	// Olson's search maximises the scan's likelihood times the motion
	// prior: each scored point as one unit of log-likelihood, the guess as
	// a Gaussian. Where the scan decides (a score difference of a few
	// points) the prior does not matter; along a corridor, where the scan
	// scores a whole ridge alike, the guess picks the place on it.
	const Eigen::Matrix3d Pinv = guess.cov.asEigen().inverse();
	const Result::Contender* top = nullptr;
	double topLogPosterior = 0;
	for (const auto& f : found)
	{
		const double lp = static_cast<double>(n) * f.score -
			0.5 * guessMahalanobis2(f.pose, guess.mean, Pinv);
		if (!top || lp > topLogPosterior)
		{
			top = &f;
			topLogPosterior = lp;
		}
	}
	r.best = top->pose;
	r.bestScore = top->score;
	// Contenders: the best poses distinct from the best and from one another
	// (a peak's own neighbours are not contenders).
	for (const auto& f : found)
	{
		if (r.contenders.size() >= kMaxContenders) break;
		bool isNew = distinct(f.pose, r.best);
		for (const auto& c : r.contenders) isNew = isNew && distinct(f.pose, c.pose);
		if (isNew) r.contenders.push_back(f);
	}

	if (r.bestScore < options.minScore)
	{
		char buf[300];
		std::snprintf(buf, sizeof(buf),
			"coarse search: at best %.0f%% of the current points lie on the reference "
			"(coarse_min_score %.0f%%): too little overlap in the window (+-%.2f m, +-%.1f deg)",
			100 * r.bestScore, 100 * options.minScore, std::max(r.windowXY[0], r.windowXY[1]),
			mrpt::RAD2DEG(r.windowYaw));
		r.failureReason = buf;
		return r;
	}
	r.success = true;
	return r;
}

std::vector<CorrelativeScanSearch::Result::Contender> CorrelativeScanSearch::branchAndBound(
	const mrpt::poses::CPosePDFGaussian& guess, Result& r)
{
	CorrelationTables::Window w;
	w.centre = guess.mean;
	w.yawStep = r.yawStep;
	w.nYaw = static_cast<int>(std::ceil(r.windowYaw / r.yawStep));
	w.nx = static_cast<int>(std::ceil(r.windowXY[0] / r.resolution));
	w.ny = static_cast<int>(std::ceil(r.windowXY[1] / r.resolution));
	// Go on below the best to find the contenders too.
	const double keepGoing = options.ambiguityZ > 0 ? options.contenderRatio : 1.0;
	// The same points, window and ratio on the same tables give the same
	// poses: a fallback's search of its matcher's pair is not run twice.
	const std::vector<CorrelationTables::Candidate>* kept =
		m_ref->lastSearch(m_px, m_py, w, keepGoing);
	std::vector<CorrelationTables::Candidate> fresh;
	if (!kept)
	{
		fresh = m_ref->tables.search(m_px, m_py, w, keepGoing);
		m_ref->rememberSearch(m_px, m_py, w, keepGoing, fresh);
		kept = &fresh;
	}
	std::vector<Result::Contender> found;
	for (const auto& c : *kept) found.push_back({c.pose, c.score});
	return found;
}

void CorrelativeScanSearch::sharpScores(
	const mrpt::poses::CPose2D& pose, std::vector<double>& out) const
{
	out.assign(m_allX.size(), 0.0);
	if (!m_ref || m_ref->tables.empty()) return;
	const double c = std::cos(pose.phi()), s = std::sin(pose.phi());
	const double k = -0.5 / (m_ref->sharpSigma * m_ref->sharpSigma);
	for (size_t i = 0; i < m_allX.size(); i++)
	{
		const double d = m_ref->tables.distanceAt(c * m_allX[i] - s * m_allY[i] + pose.x(),
			s * m_allX[i] + c * m_allY[i] + pose.y());
		if (d >= 0) out[i] = std::exp(k * d * d);
	}
}

mrpt::poses::CPose2D CorrelativeScanSearch::bestGridNeighbour(
	const Result& r, const mrpt::poses::CPose2D& o, std::vector<double>& scores) const
{
	double best = -1;
	mrpt::poses::CPose2D at = o;
	std::vector<double> s;
	for (int dw = -1; dw <= 1; dw++)
		for (int dx = -1; dx <= 1; dx++)
			for (int dy = -1; dy <= 1; dy++)
			{
				const mrpt::poses::CPose2D p(
					o.x() + dx * r.resolution, o.y() + dy * r.resolution, o.phi() + dw * r.yawStep);
				sharpScores(p, s);
				const double sc = mean(s);
				if (sc > best)
				{
					best = sc;
					at = p;
					scores.swap(s);
				}
			}
	return at;
}

CorrelativeScanSearch::Ambiguity CorrelativeScanSearch::ambiguity(const Result& r,
	const mrpt::poses::CPose2D& estimate, const mrpt::poses::CPosePDFGaussian& guess) const
{
	Ambiguity out;
	if (options.ambiguityZ <= 0) return out;
	// A contender the guess itself rules out is no ambiguity: the search's
	// window is wider than the guess's covariance (its minimum absorbs
	// over-confident odometry), and an accurate guess decides between two
	// solutions that the scan cannot tell apart.
	const Eigen::Matrix3d Pinv = guess.cov.asEigen().inverse();
	std::vector<double> atEstimate, atRival;
	sharpScores(estimate, atEstimate);
	std::vector<mrpt::poses::CPose2D> others;
	for (const auto& c : r.contenders) others.push_back(c.pose);
	others.push_back(r.best);  // the estimate may have left the search's best
	for (const auto& o : others)
	{
		if (!distinct(o, estimate) || guessMahalanobis2(o, guess.mean, Pinv) > kPlausibleChi2)
			continue;
		// The contender sits on the search grid: it gets its best grid
		// neighbour, so that quantisation does not favour the (continuous)
		// estimate by much.
		const mrpt::poses::CPose2D at = bestGridNeighbour(r, o, atRival);
		const double z = evidence(atEstimate, atRival);
		if (z >= options.ambiguityZ || !distinct(at, estimate)) continue;
		out.rivals.push_back(at);
		out.ambiguous = true;
		const auto d = at - estimate;
		char buf[320];
		std::snprintf(buf, sizeof(buf),
			"ambiguous: a solution %.2f m, %.1f deg from the estimate puts %.0f%% of the points "
			"on the reference against %.0f%% at the estimate (evidence for the estimate z = "
			"%.1f < coarse_ambiguity_z %.1f)",
			std::hypot(d.x(), d.y()), mrpt::RAD2DEG(d.phi()), 100 * mean(atRival),
			100 * mean(atEstimate), z, options.ambiguityZ);
		out.reasons.push_back(buf);
	}
	if (out.ambiguous) out.reason = out.reasons.front();
	return out;
}

double CorrelativeScanSearch::evidence(const std::vector<double>& a,
	const std::vector<double>& b, const std::vector<uint32_t>& group)
{
	double sum = 0, sum2 = 0, object = 0;
	for (size_t i = 0; i < a.size(); i++)
	{
		object += a[i] - b[i];
		if (!group.empty() && i + 1 < a.size() && group[i + 1] == group[i]) continue;
		sum += object;
		sum2 += object * object;
		object = 0;
	}
	return sum2 > 0 ? sum / std::sqrt(sum2) : 0.0;
}

std::vector<uint32_t> CorrelativeScanSearch::objectGroups(double span) const
{
	std::vector<uint32_t> group(m_allX.size(), 0);
	size_t first = 0;
	for (size_t i = 1; i < m_allX.size(); i++)
	{
		if (std::hypot(m_allX[i] - m_allX[first], m_allY[i] - m_allY[first]) > span)
			first = i;
		group[i] = static_cast<uint32_t>(first);
	}
	return group;
}

double CorrelativeScanSearch::evidenceFor(
	const mrpt::poses::CPose2D& a, const mrpt::poses::CPose2D& b, double objectSpan) const
{
	std::vector<double> atA, atB;
	sharpScores(a, atA);
	sharpScores(b, atB);
	return evidence(atA, atB, objectSpan > 0 ? objectGroups(objectSpan) : std::vector<uint32_t>{});
}

bool CorrelativeScanSearch::distinct(const mrpt::poses::CPose2D& a, const mrpt::poses::CPose2D& b) const
{
	return !posesWithin(a, b, options.distinctXY, options.distinctYaw);
}
}  // namespace featloc
