#include "featloc/matchers/ScanMatcher.h"

#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/math/wrap2pi.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/system/string_utils.h>

#include <Eigen/Dense>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>

#include "featloc/config/ConfigValues.h"
#include "featloc/core/ConfigError.h"
#include "featloc/math/PoseDifference.h"
#include "featloc/matchers/ReferenceOverlap.h"
#include "featloc/matchers/ScanMatcherFactory.h"

namespace featloc
{
IMPLEMENTS_VIRTUAL_MRPT_OBJECT(ScanMatcher, mrpt::rtti::CObject, featloc)

namespace
{
/** Fewer points than this cannot constrain a planar motion (3 dof). */
constexpr size_t kMinPointsPerScan = 3;

mrpt::poses::CPose2D planar(const mrpt::poses::CPose3D& p)
{
	return mrpt::poses::CPose2D(p);
}
}  // namespace

void ScanMatcher::loadParams(const mrpt::config::CConfigFileBase& cfg, const std::string& section)
{
	loadParams(cfg, section, true);
}

void ScanMatcher::loadParams(
	const mrpt::config::CConfigFileBase& cfg, const std::string& section, bool followFallback)
{
	m_coarse.options.loadFromConfigFile(cfg, section);
	config::read(cfg, section, "fallback_class", m_fallbackClass);
	m_fallbackClass = mrpt::system::trim(m_fallbackClass);
	config::read(cfg, section, "fallback_on_ambiguity", m_fallbackOnAmbiguity);
	config::read(cfg, section, "fallback_shares_tables", m_fallbackSharesTables);
	config::read(cfg, section, "fallback_above_sigma_xy", m_fallbackAboveSigmaXY);
	if (!(m_fallbackAboveSigmaXY >= 0))
		config::fail(cfg, section, "fallback_above_sigma_xy",
			"must be a sigma in metres, >= 0 (0: off)");
	config::read(cfg, section, "free_direction_from_guess", m_freeDirectionFromGuess);
	config::read(cfg, section, "dequantize_ranges", m_dequantizeRanges);
	config::read(cfg, section, "dequantize_extremum_chord", m_lattice.maxExtremumChord);
	if (!(m_lattice.maxExtremumChord >= 0))
		config::fail(cfg, section, "dequantize_extremum_chord", "must be a length in metres, >= 0 (0: off)");
	m_fallback.reset();
	m_followFallback = followFallback;
	if (followFallback && !m_fallbackClass.empty())
	{
		try
		{
			m_fallback = ScanMatcherFactory::create(m_fallbackClass);
		}
		catch (const ConfigError& e)
		{
			config::fail(cfg, section, "fallback_class", e.what());
		}
		if (m_fallback->className() == className())
			config::fail(cfg, section, "fallback_class",
				"names the matcher itself (" + className() +
					"); a fallback must be another class");
		m_fallback->loadParams(
			cfg, ScanMatcherFactory::paramsSection(m_fallback->className()), false);
		if (m_fallbackSharesTables) m_fallback->m_coarse.shareTablesWith(m_coarse);
	}
	loadOwnParams(cfg, section);
}

void ScanMatcher::saveParams(mrpt::config::CConfigFileBase& cfg, const std::string& section) const
{
	m_coarse.options.saveToConfigFile(cfg, section);
	config::write(cfg, section, "fallback_class", m_fallbackClass,
		"matcher that takes over when this one fails, with its own section's parameters "
		"(empty: none; a fallback's own fallback_class is not followed)");
	config::write(cfg, section, "fallback_on_ambiguity", m_fallbackOnAmbiguity,
		"an ambiguous match (flagged) goes to the fallback too; the fallback's result "
		"replaces it when it is a success that is not ambiguous");
	config::write(cfg, section, "fallback_shares_tables", m_fallbackSharesTables,
		"the fallback uses this matcher's coarse-search tables of the reference and its last "
		"branch and bound where its own would be the same (the same results, faster; false: "
		"each builds and searches its own)");
	config::write(cfg, section, "fallback_above_sigma_xy", m_fallbackAboveSigmaXY,
		"[m] a successful, unflagged match whose covariance leaves a translation sigma above "
		"this (and above a range lattice's cell) goes to the fallback too; the fallback's "
		"result replaces it when it is a success that is not ambiguous (0: off)");
	config::write(cfg, section, "free_direction_from_guess", m_freeDirectionFromGuess,
		"a match that fails only because its points leave one direction free (a corridor) "
		"keeps the guess along it and the match across it, flagged ambiguous");
	config::write(cfg, section, "dequantize_ranges", m_dequantizeRanges,
		"readings on a range lattice (RangeLattice: MRPT's simulated log, 0.16 m; some real "
		"logs, 2.5-5 cm) are put back on their surfaces from the lattice's level crossings "
		"before matching, and the covariance takes the lattice's cell as its least range noise");
	config::write(cfg, section, "dequantize_extremum_chord", m_lattice.maxExtremumChord,
		"[m] dequantize_ranges: a surface's nearest (or farthest) run of readings on one level, "
		"between two anchors on the same level boundary, is kept on its level where its chord "
		"is at most this long and the anchors beyond do not confirm a flat surface: on a round "
		"thing the chord differs from each viewpoint (0: on the chord; off by default: it "
		"helped the simulated office and hurt edmonton, doc/benchmarks.md)");
	saveOwnParams(cfg, section);
}

double ScanMatcher::weakTranslationSigma(const MatchResult& r) const
{
	if (m_fallbackAboveSigmaXY <= 0 || !r.success || r.ambiguous) return 0;
	const Eigen::Matrix2d xy = r.estimate.cov.asEigen().topLeftCorner<2, 2>();
	const double sigma =
		std::sqrt(std::max(0.0, Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(xy).eigenvalues()[1]));
	return sigma > std::max(m_fallbackAboveSigmaXY, rangeLatticeCellSigma()) ? sigma : 0;
}

template <typename Run>
MatchResult ScanMatcher::tryFallback(MatchResult r, Run&& run)
{
	m_lastMatchByFallback = false;
	const bool ambiguous = r.success && r.ambiguous && m_fallbackOnAmbiguity;
	// A match whose own covariance says its geometry fixes the position
	// poorly: PCM's with a translation sigma of 1-2 cm or more were 2-4 mm
	// worse than IDC's on the same pairs of orebro (calibration), where
	// IDC keeps every point and PCM only its lines and ellipses.
	const double weakSigma = weakTranslationSigma(r);
	if ((r.success && !ambiguous && weakSigma <= 0) || r.failureKind == "too_few_points") return r;
	// A matcher used without loadParams() has its default fallback, with
	// that class's default parameters.
	if (!m_fallback && m_followFallback && !m_fallbackClass.empty())
	{
		m_fallback = ScanMatcherFactory::create(m_fallbackClass);
		m_fallback->m_followFallback = false;
		if (m_fallbackSharesTables) m_fallback->m_coarse.shareTablesWith(m_coarse);
	}
	if (!m_fallback) return r;
	m_fallback->m_guessGateEnabled = m_guessGateEnabled;
	MatchResult f = run(*m_fallback);
	if (r.success)
	{
		// An ambiguous (or weak) match is used; a fallback's match that
		// the points do not find ambiguous is better evidence. PCM's
		// ambiguous estimates were the wrong solution more often than
		// IDC's on the same pairs (orebro, calibration: 125 against 58 mm
		// mean error); a flagged match of the fallback is no better than
		// the matcher's own, which stays.
		if (!f.success || f.ambiguous)
		{
			r.timeSeconds += f.timeSeconds;
			return r;
		}
		if (ambiguous)
			f.primaryFailure = className() + ": ambiguous, " + r.ambiguityReason;
		else
		{
			char buf[160];
			std::snprintf(buf, sizeof(buf),
				": weak, its translation sigma %.3f m > fallback_above_sigma_xy %.3f m",
				weakSigma, m_fallbackAboveSigmaXY);
			f.primaryFailure = className() + buf;
		}
	}
	else
		f.primaryFailure = className() + ": " + r.failureReason;
	if (!f.success)
		f.failureReason = "the fallback " + m_fallback->className() + " failed too: " +
			f.failureReason + " (after " + f.primaryFailure + ")";
	f.timeSeconds += r.timeSeconds;
	m_lastMatchByFallback = true;
	return f;
}

std::string ScanMatcher::className() const
{
	return GetRuntimeClass()->className;
}

MatchResult ScanMatcher::match(
	const mrpt::obs::CObservation2DRangeScan& reference,
	const mrpt::obs::CObservation2DRangeScan& current,
	const mrpt::poses::CPosePDFGaussian& initialGuess,
	const mrpt::math::CMatrixDouble33& gateAllowance)
{
	const auto t0 = std::chrono::steady_clock::now();
	const mrpt::poses::CPose2D s1 = planar(reference.sensorPose);
	const mrpt::poses::CPose2D s2 = planar(current.sensorPose);

	// Robot motion X, sensor motion Y: X = S1 (+) Y (+) S2^-1, hence
	// Y = S1^-1 (+) X (+) S2. MRPT propagates the covariance through both
	// compositions with their Jacobians: on the left changeCoordinatesReference
	// rotates it by S1's heading; on the right only the composition with a
	// pose PDF (of zero covariance) applies d(X (+) U)/dX, the lever arm of
	// the rotation. (MRPT 2.5's operator+=(CPose2D) instead rotates the
	// covariance by U's heading: with a sensor turned 90 deg on the robot the
	// two rotations cancelled and x and y stayed swapped.)
	auto toSensorFrames = [&](mrpt::poses::CPosePDFGaussian g) {
		g.changeCoordinatesReference(mrpt::poses::CPose2D() - s1);
		g += mrpt::poses::CPosePDFGaussian(s2);
		return g;
	};
	auto toRobotFrames = [&](mrpt::poses::CPosePDFGaussian& g) {
		g.changeCoordinatesReference(s1);
		g += mrpt::poses::CPosePDFGaussian(mrpt::poses::CPose2D() - s2);
	};
	// The coarse search's window also covers what the gate allows for.
	mrpt::poses::CPosePDFGaussian window = initialGuess;
	window.cov += gateAllowance;

	ScanPoints refPoints = ScanPoints::fromScan(reference);
	ScanPoints curPoints = ScanPoints::fromScan(current);
	m_rangeLatticeStep = 0;
	if (m_dequantizeRanges || usesRangeLatticeStep())
	{
		undoRangeLattice(refPoints);
		m_rangeLatticeStep = undoRangeLattice(curPoints);
	}
	const mrpt::poses::CPosePDFGaussian sensorWindow = toSensorFrames(window);
	MatchResult r =
		matchInSensorFrames(refPoints, curPoints, toSensorFrames(initialGuess), sensorWindow);
	r.rangeLatticeStep = m_rangeLatticeStep;
	r.rangesDequantized = m_dequantizeRanges && m_rangeLatticeStep > 0;
	const mrpt::poses::CPose2D sensorEstimate = r.estimate.mean;

	toRobotFrames(r.estimate);
	if (r.freeDirection.asEigen().squaredNorm() > 0)
	{
		// The direction as the estimate's covariance goes: through the
		// Jacobians of both compositions (a lever arm turns a rotation
		// into a translation too).
		mrpt::poses::CPosePDFGaussian along(sensorEstimate,
			mrpt::math::CMatrixDouble33(
				r.freeDirection.asEigen() * r.freeDirection.asEigen().transpose()));
		toRobotFrames(along);
		const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(along.cov.asEigen());
		r.freeDirection = eig.eigenvectors().col(2);
	}
	r.gateAllowance = gateAllowance;
	r.guess = initialGuess;
	r.referenceTime = reference.timestamp;
	// In the robot frame, where the guess's uncertainty is what its
	// source (odometry) says; in the sensor frames a lever arm couples it.
	checkAgainstGuess(initialGuess, r);
	if (r.rejectedByGuessGate)
		arbitrateGuessGate(refPoints, curPoints, sensorWindow.mean, sensorEstimate, r);
	r.timeSeconds =
		std::chrono::duration<double>(std::chrono::steady_clock::now() - t0)
			.count();
	return tryFallback(std::move(r), [&](ScanMatcher& f) {
		return f.match(reference, current, initialGuess, gateAllowance);
	});
}

double ScanMatcher::rangeLatticeCellSigma() const
{
	return m_rangeLatticeStep / std::sqrt(12.0);
}

double ScanMatcher::undoRangeLattice(ScanPoints& scan)
{
	// The lattice is found on the readings as they came (the remembered
	// scan is kept as it came too).
	if (!scan.samePointsAs(m_latticeScan))
	{
		m_latticeScanStep = m_lattice.step(scan);
		m_latticeScanOffset = m_lattice.offset();
		m_latticeScan = scan;
	}
	if (m_latticeScanStep > 0 && m_dequantizeRanges)
		m_lattice.dequantize(scan, m_latticeScanStep, m_latticeScanOffset);
	return m_latticeScanStep;
}

void ScanMatcher::arbitrateGuessGate(const ScanPoints& reference, const ScanPoints& current,
	const mrpt::poses::CPose2D& guess, const mrpt::poses::CPose2D& estimate, MatchResult& r)
{
	const double minZ = m_coarse.options.overruleGuessZ;
	if (minZ <= 0 || m_coarse.options.ambiguityZ <= 0) return;
	// The gate fired: the guess is wrong by more than its covariance says,
	// or the estimate is, so that covariance cannot bound where the truth
	// may be. One search over the widest window (coarse_max_window_*)
	// around the guess scores the guess's solutions and the matcher's on
	// one table; every pose of it can be a rival. (A window grown only to
	// take in the estimate missed a corridor's stretch beyond it, where the
	// truth was.)
	const double sigmas = m_coarse.options.windowSigmas;
	const double sxy = m_coarse.options.maxWindowXY / sigmas;
	const double syaw = m_coarse.options.maxWindowYaw / sigmas;
	const mrpt::poses::CPosePDFGaussian widest(guess,
		mrpt::math::CMatrixDouble33(
			Eigen::Vector3d(sxy * sxy, sxy * sxy, syaw * syaw).asDiagonal().toDenseMatrix()));
	const CorrelativeScanSearch::Result coarse = m_coarse.search(reference, current, widest);
	if (!coarse.success || m_coarse.distinct(coarse.best, estimate)) return;
	if (m_coarse.ambiguity(coarse, estimate, widest).ambiguous) return;
	// Each object of the scan is one witness (coarse_overrule_object_span):
	// a person walking with the robot puts 30 points on the reference at a
	// pose that is wrong by half a metre, and counted point by point they
	// outvoted the corridor's static door recess (doc/benchmarks.md, "Issue
	// 15, twenty-third session").
	const double z = m_coarse.evidenceFor(estimate, guess, m_coarse.options.overruleObjectSpan);
	if (z < minZ) return;
	char buf[200];
	std::snprintf(buf, sizeof(buf),
		"; overruled: a correlative search of the widest window around the guess finds the "
		"estimate, unambiguous, and the scan's objects favour it over the guess by z = %.1f",
		z);
	r.success = true;
	r.rejectedByGuessGate = false;
	r.failureKind.clear();
	r.guessGateOverruled = r.failureReason + buf;
	r.failureReason.clear();
}

MatchResult ScanMatcher::match(
	const ScanPoints& reference, const ScanPoints& current,
	const mrpt::poses::CPosePDFGaussian& initialGuess)
{
	const auto t0 = std::chrono::steady_clock::now();
	// No lattice is looked for here: no floor from an earlier match of
	// observations may remain.
	m_rangeLatticeStep = 0;
	MatchResult r = matchInSensorFrames(reference, current, initialGuess, initialGuess);
	r.guess = initialGuess;
	checkAgainstGuess(initialGuess, r);
	if (r.rejectedByGuessGate)
		arbitrateGuessGate(reference, current, initialGuess.mean, r.estimate.mean, r);
	r.timeSeconds =
		std::chrono::duration<double>(std::chrono::steady_clock::now() - t0)
			.count();
	return tryFallback(std::move(r),
		[&](ScanMatcher& f) { return f.match(reference, current, initialGuess); });
}

void ScanMatcher::checkAgainstGuess(
	const mrpt::poses::CPosePDFGaussian& guess, MatchResult& r) const
{
	const double gate = m_guessGateEnabled ? guessGateChi2() : 0.0;
	if (!r.success || gate <= 0) return;
	const Eigen::Vector3d d = poseDifference(r.estimate.mean, guess.mean);
	const Eigen::Matrix3d P =
		guess.cov.asEigen() + r.estimate.cov.asEigen() + r.gateAllowance.asEigen();
	const double m2 = d.dot(P.ldlt().solve(d));
	if (m2 <= gate) return;
	char buf[220];
	std::snprintf(buf, sizeof(buf),
		"the estimate is implausibly far from the initial guess (Mahalanobis^2 %.1f > "
		"guess_gate_chi2 %.1f: moved %.3f m, %.2f deg)",
		m2, gate, std::hypot(d[0], d[1]), mrpt::RAD2DEG(d[2]));
	r.success = false;
	r.rejectedByGuessGate = true;
	r.failureKind = "guess_gate";
	r.failureReason = buf;
}

MatchResult ScanMatcher::matchInSensorFrames(
	const ScanPoints& reference, const ScanPoints& current,
	const mrpt::poses::CPosePDFGaussian& initialGuess,
	const mrpt::poses::CPosePDFGaussian& window)
{
	MatchResult r;
	r.estimate = initialGuess;
	r.referencePoints = reference.size();
	r.currentPoints = current.size();
	if (reference.size() < kMinPointsPerScan ||
		current.size() < kMinPointsPerScan)
	{
		r.success = false;
		r.failureKind = "too_few_points";
		r.failureReason = "too few valid points (reference " +
			std::to_string(reference.size()) + ", current " +
			std::to_string(current.size()) + "; need at least " +
			std::to_string(kMinPointsPerScan) + ")";
	}
	else if (m_coarse.options.enabled)
	{
		if (!matchConfirmedFromGuess(reference, current, initialGuess, window, r))
			matchFromCoarseSearch(reference, current, window, r);
	}
	else
		matchPointsFinite(reference, current, initialGuess, r);
	// Every failure has a kind; the matcher's own reasons are "matcher".
	if (!r.success && r.failureKind.empty()) r.failureKind = "matcher";
	if (!r.success && r.failureKind == "matcher" && m_freeDirectionFromGuess &&
		r.freeDirection.asEigen().squaredNorm() > 0)
		keepGuessAlongFreeDirection(window, r);
	else if (!r.success)
		r.freeDirection = mrpt::math::CVectorFixedDouble<3>();
	return r;
}

void ScanMatcher::keepGuessAlongFreeDirection(
	const mrpt::poses::CPosePDFGaussian& window, MatchResult& r)
{
	// Along a corridor the scans fix the heading and the cross-track
	// position, not where along it: failing the whole match would throw
	// the two away with the third (a failure is counted, and used, at the
	// guess's error). The guess is one scalar measurement along w, of the
	// guess's own variance there; the matcher's estimate carries next to
	// no information along w (kUnconstrainedVariance, or a sigma beyond
	// max_translation_sigma), so the update takes the guess's position
	// there and leaves the rest as the matcher had it, with the
	// covariance what the guess knows along w and the points across it.
	const Eigen::Vector3d w = r.freeDirection.asEigen().normalized();
	const Eigen::Matrix3d C = r.estimate.cov.asEigen();
	const Eigen::Vector3d Cw = C * w;
	const double innovation = w.dot(poseDifference(window.mean, r.estimate.mean));
	const double S = w.dot(Cw) + w.dot(window.cov.asEigen() * w);
	const Eigen::Vector3d step = Cw * (innovation / S);
	const mrpt::poses::CPose2D& x = r.estimate.mean;
	r.estimate.mean = mrpt::poses::CPose2D(
		x.x() + step[0], x.y() + step[1], mrpt::math::wrapToPi(x.phi() + step[2]));
	r.estimate.cov = mrpt::math::CMatrixDouble33(Eigen::Matrix3d(C - Cw * Cw.transpose() / S));
	r.success = true;
	r.ambiguous = true;
	r.guessKeptAlongFreeDirection = true;
	r.ambiguityReason = r.failureReason + ": the guess is kept along it (free_direction_from_guess)";
	r.failureReason.clear();
	r.failureKind.clear();
}

namespace
{
/** Whether, where `estimate`'s largest sigma reaches confirmProbeSigma, a
 * pose slid along its least certain motion puts at least as large a share
 * of the points within confirmDistance as the estimate does (`share`):
 * then the estimate is not where the points peak along that direction, and
 * its confirmation says nothing about where along it the scan lies. With
 * confirmProbeTurn that motion includes its turn (the yaw scaled by the
 * points' RMS range) and the pose turns about the motion's centre; else it
 * is the least certain translation, the heading kept.
 *  - 2 or 4 x confirmDistance either way. Found on a warehouse aisle with
 *    MRPT's 0.16 m range lattice (doc/benchmarks.md, "Issue 15, nineteenth
 *    session"): IDC's iterations from a guess 0.27 m off stopped 0.26 m off
 *    with 87% of the points within 5 cm, and the pose 0.2 m towards the
 *    truth put 90% there.
 *  - With confirmProbeWindow, every confirmDistance out to the edges of
 *    the window the search would cover (`window`,
 *    CorrelativeScanSearch::halfWindow). Found on the same aisle with 1 cm
 *    noise and nothing on a lattice (twenty-fourth session): CF-IDC's
 *    iterations from a guess 0.5 m off stopped one upright's bay, 0.74 m,
 *    along the aisle with 90% of the points within 5 cm and a plateau of
 *    88-90% on either side; the truth put 96% there.
 *  - The turn: found in a round hall with 5-degree facets (twenty-ninth
 *    session): IDC's iterations from a guess 0.35 m / 5 deg off stopped
 *    turned one facet about the hall's centre, 0.26 m off, with the share
 *    confirmed and a 0.07 deg sigma; a straight slide along the least
 *    certain translation leaves the wall, the turn about the centre keeps
 *    it.
 * At a right estimate the few points that fix the position along an aisle
 * (its uprights, its ends) leave the reference when it slides, and the
 * share drops. */
bool aSlidPoseFitsAsWell(const ScanPoints& reference, const ScanPoints& current,
	const mrpt::poses::CPosePDFGaussian& estimate, double share,
	const CorrelativeScanSearch& search, const mrpt::poses::CPosePDFGaussian& window)
{
	const CorrelativeScanSearch::Options& o = search.options;
	// The least certain motion v = (vx, vy, w) per metre the points move:
	// with confirmProbeTurn, of the covariance with the yaw scaled by the
	// points' RMS range ell (a turn of w moves them by about ell w).
	double ell = 0;
	if (o.confirmProbeTurn)
	{
		for (const auto& p : current.points) ell += p.range * p.range;
		ell = std::sqrt(ell / static_cast<double>(std::max<size_t>(1, current.size())));
	}
	Eigen::Vector3d v = Eigen::Vector3d::Zero();
	if (ell > 0)
	{
		const Eigen::DiagonalMatrix<double, 3> D(1.0, 1.0, ell);
		const Eigen::Matrix3d S = D * estimate.cov.asEigen() * D;
		const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(S);
		if (eig.eigenvalues()[2] < o.confirmProbeSigma * o.confirmProbeSigma) return false;
		const Eigen::Vector3d u = eig.eigenvectors().col(2);
		v = Eigen::Vector3d(u[0], u[1], u[2] / ell);
	}
	else
	{
		const Eigen::Matrix2d P = estimate.cov.asEigen().block<2, 2>(0, 0);
		const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(P);
		if (eig.eigenvalues()[1] < o.confirmProbeSigma * o.confirmProbeSigma) return false;
		v.head<2>() = eig.eigenvectors().col(1);
	}
	const mrpt::poses::CPose2D& x = estimate.mean;
	// The pose moved t along v: for w != 0 turned by t w about the centre
	// c = (x, y) + J (vx, vy) / w of the motion v (J a quarter turn), the
	// translation t (a vx - b vy, a vy + b vx) with a = sin(tw) / (tw),
	// b = (1 - cos(tw)) / (tw), which is t (vx, vy) as w -> 0.
	auto slid = [&](double t) {
		const double th = t * v[2];
		const double a = std::abs(th) < 1e-9 ? 1.0 : std::sin(th) / th;
		const double b = std::abs(th) < 1e-9 ? 0.0 : (1 - std::cos(th)) / th;
		return mrpt::poses::CPose2D(x.x() + t * (a * v[0] - b * v[1]),
			x.y() + t * (a * v[1] + b * v[0]), x.phi() + th);
	};
	auto fits = [&](const mrpt::poses::CPose2D& p) {
		return ReferenceOverlap::share(reference, current, p, o.confirmDistance, share) >= share;
	};
	const double d = o.confirmDistance;
	for (const double steps : {-2.0, 2.0, -4.0, 4.0})
		if (fits(slid(steps * d))) return true;
	if (!o.confirmProbeWindow) return false;
	// Out to the edges of the search's window, a box around its mean.
	const CorrelativeScanSearch::HalfWindow h = search.halfWindow(window);
	const bool turns = v[2] != 0;
	auto inside = [&](const mrpt::poses::CPose2D& p) {
		return std::abs(p.x() - window.mean.x()) <= h.xy[0] &&
			std::abs(p.y() - window.mean.y()) <= h.xy[1] &&
			std::abs(mrpt::math::wrapToPi(p.phi() - window.mean.phi())) <= h.yaw;
	};
	// How far along v the window reaches (`end`), and the length that
	// sets the step (`span`): at most kMaxSteps slid poses each way,
	// whatever confirmDistance is. A translation's line x + t v crosses
	// the box between lo and hi; a turn's arc ends where its heading, or
	// to first order its position, has crossed the whole box (at most half
	// a revolution), and only its poses inside the box are tried.
	double span = 0, end = 0;
	double lo = -std::numeric_limits<double>::infinity(), hi = -lo;
	if (!turns)
	{
		const double offset[2] = {x.x() - window.mean.x(), x.y() - window.mean.y()};
		for (int i = 0; i < 2; i++)
		{
			if (std::abs(v[i]) < 1e-9) continue;
			const double a = (-h.xy[i] - offset[i]) / v[i], b = (h.xy[i] - offset[i]) / v[i];
			lo = std::max(lo, std::min(a, b));
			hi = std::min(hi, std::max(a, b));
		}
		if (!std::isfinite(lo) || !std::isfinite(hi)) return false;  // no window to slide in
		span = std::max(std::abs(lo), std::abs(hi));
		end = std::max(-lo, hi);
	}
	else
	{
		span = std::min(2 * h.yaw, M_PI) / std::abs(v[2]);
		for (int i = 0; i < 2; i++)
			if (std::abs(v[i]) > 1e-9) span = std::min(span, 2 * h.xy[i] / std::abs(v[i]));
		if (!std::isfinite(span)) return false;
		end = span;
	}
	constexpr double kMaxSteps = 64;
	const double step = std::max(d, span / kMaxSteps);
	auto probe = [&](double t) {  // t != 0
		if (!turns && (t > 0 ? t > hi : t < lo)) return false;
		const mrpt::poses::CPose2D p = slid(t);
		return (!turns || inside(p)) && fits(p);
	};
	for (double t = 4 * d + step; t <= end; t += step)
		if (probe(t) || probe(-t)) return true;
	return false;
}
}  // namespace

void ScanMatcher::matchPointsFinite(const ScanPoints& reference, const ScanPoints& current,
	const mrpt::poses::CPosePDFGaussian& initialGuess, MatchResult& r)
{
	matchPoints(reference, current, initialGuess, r);
	if (!r.success) return;
	// A success whose estimate or covariance is not finite is no match:
	// what follows (the confirmation probe's slides, the EKF's update) would
	// take it as one, and the probe's slides along a NaN direction never end.
	const auto& m = r.estimate.mean;
	if (std::isfinite(m.x()) && std::isfinite(m.y()) && std::isfinite(m.phi()) &&
		r.estimate.cov.asEigen().allFinite())
		return;
	r.success = false;
	r.failureKind = "non_finite";
	r.failureReason = "the matcher's estimate or its covariance is not finite (NaN or infinite)";
}

bool ScanMatcher::matchConfirmedFromGuess(const ScanPoints& reference,
	const ScanPoints& current, const mrpt::poses::CPosePDFGaussian& initialGuess,
	const mrpt::poses::CPosePDFGaussian& window, MatchResult& r)
{
	const double minShare = m_coarse.options.confirmShare;
	if (minShare <= 0) return false;
	// The search costs ten to twenty times the iterations on a 361-beam
	// scan; where the iterations from the guess already land on a pose
	// that the reference confirms point by point, it would start them at
	// that same pose. A wrong minimum leaves points off the reference: on
	// the calibration scenes, without the search, 0.06-0.52 (10th-90th
	// percentile) of the points of orebro's gross errors lay within 5 cm,
	// against 0.86-0.99 on the simulated office. The search runs then, as
	// it does on a failure. (10 cm was too loose: a room pair 86 mm off
	// had 0.90 of its points within 10 cm and 0.27 within 5 cm; IDC's
	// slides along the corridor with people passed at 10 cm and not at
	// 5 cm.) Along a corridor a slid pose is confirmed as well as the
	// right one: the featloc matchers' own checks fail a match whose
	// points leave a direction free (MotionConstraintCheck), which is why
	// IcpMatcher, whose covariance does not, has this off; where the
	// points fix that direction only weakly, the confirmation must also
	// fail at slid poses (coarse_confirm_probe).
	MatchResult local = r;
	matchPointsFinite(reference, current, initialGuess, local);
	if (!local.success) return false;
	const double share = ReferenceOverlap::share(
		reference, current, local.estimate.mean, m_coarse.options.confirmDistance, minShare);
	if (share < minShare) return false;
	if (m_coarse.options.confirmProbe &&
		aSlidPoseFitsAsWell(reference, current, local.estimate, share, m_coarse, window))
	{
		r.confirmationSlid = true;
		return false;
	}
	r = std::move(local);
	r.confirmedShare = share;
	return true;
}

void ScanMatcher::matchFromCoarseSearch(const ScanPoints& reference, const ScanPoints& current,
	const mrpt::poses::CPosePDFGaussian& window, MatchResult& r)
{
	const CorrelativeScanSearch::Result coarse = m_coarse.search(reference, current, window);
	r.coarseScore = coarse.bestScore;
	if (!coarse.success)
	{
		r.success = false;
		r.failureKind = "no_overlap";
		r.failureReason = coarse.failureReason;
		return;
	}
	matchPointsFinite(reference, current,
		mrpt::poses::CPosePDFGaussian(coarse.best, coarse.gridCovariance()), r);
	if (!r.success) return;
	// The estimate against the search's other solutions (and its own best,
	// if the iterations walked away from it into another minimum). Refining
	// the rival too and keeping the better refinement was tried: it moved
	// few matches from flagged to right and some to silently wrong (people
	// walking).
	auto amb = m_coarse.ambiguity(coarse, r.estimate.mean, window);
	if (!amb.ambiguous) return;
	if (m_coarse.options.refineRivals)
	{
		amb = rivalsOfTheirOwn(reference, current, coarse, amb, r);
		if (!amb.ambiguous) return;
	}
	// Iterations that converged outside the window the search scored went
	// where the search did not look. If the estimate is clearly better than
	// all the search saw, the window was too narrow for the guess's error
	// and the estimate stands; if not, inflating its covariance to reach
	// back into the window would let the guess gate pass a wrong match (a
	// CF-IDC match of 80 points on the 1 cm office, seed 2, walked 1.6 m
	// from the search's best and ruined the run): it fails.
	const Eigen::Vector3d off = poseDifference(r.estimate.mean, window.mean);
	if (std::abs(off[0]) > coarse.windowXY[0] + coarse.resolution ||
		std::abs(off[1]) > coarse.windowXY[1] + coarse.resolution ||
		std::abs(off[2]) > coarse.windowYaw + coarse.yawStep)
	{
		char buf[480];
		std::snprintf(buf, sizeof(buf),
			"the iterations left the window the coarse search scored (converged %.3f m, %.3f m, "
			"%.2f deg from the guess; window +-%.2f m, +-%.2f m, +-%.1f deg) and the estimate is "
			"not clearly better than a solution inside it: %s",
			off[0], off[1], mrpt::RAD2DEG(off[2]), coarse.windowXY[0], coarse.windowXY[1],
			mrpt::RAD2DEG(coarse.windowYaw), amb.reason.c_str());
		r.success = false;
		r.failureKind = "left_window";
		r.failureReason = buf;
		return;
	}
	if (m_coarse.options.onAmbiguity == "fail")
	{
		r.success = false;
		r.failureKind = "ambiguous";
		r.failureReason = amb.reason;
		return;
	}
	// Along a corridor the scans fix the heading and the cross-track
	// position but not where along it: each rival's offset joins the
	// covariance as one standard deviation, so it covers the rivals and
	// leaves the directions the scans do fix as they were.
	Eigen::Matrix3d C = r.estimate.cov.asEigen();
	for (const auto& rival : amb.rivals)
	{
		const Eigen::Vector3d d = poseDifference(rival, r.estimate.mean);
		C += d * d.transpose();
	}
	r.estimate.cov = mrpt::math::CMatrixDouble33(C);
	r.ambiguous = true;
	r.ambiguityReason = amb.reason;
}

CorrelativeScanSearch::Ambiguity ScanMatcher::rivalsOfTheirOwn(const ScanPoints& reference,
	const ScanPoints& current, const CorrelativeScanSearch::Result& coarse,
	const CorrelativeScanSearch::Ambiguity& amb, const MatchResult& r)
{
	// The search's score is coarse (5 cm hits, its grid's steps): along a
	// direction the scans fix only through fine structure it is flat, and
	// a rival there is a pose on the slope of the estimate's own minimum.
	// Where the iterations from the rival come back to the estimate, the
	// points have one solution there. (Keeping the better of the two
	// refinements instead was tried, above, and made silent errors with
	// people walking: here a rival is only dropped when both refinements
	// agree.)
	CorrelativeScanSearch::Ambiguity kept;
	const mrpt::math::CMatrixDouble33 cov = coarse.gridCovariance();
	for (size_t i = 0; i < amb.rivals.size(); i++)
	{
		MatchResult fromRival = r;
		matchPointsFinite(
			reference, current, mrpt::poses::CPosePDFGaussian(amb.rivals[i], cov), fromRival);
		if (fromRival.success && !m_coarse.distinct(fromRival.estimate.mean, r.estimate.mean))
			continue;
		kept.rivals.push_back(amb.rivals[i]);
		kept.reasons.push_back(amb.reasons[i]);
	}
	kept.ambiguous = !kept.rivals.empty();
	if (kept.ambiguous) kept.reason = kept.reasons.front();
	// What inspectLastMatch() reports is of the estimate's iterations.
	MatchResult again = r;
	matchPointsFinite(reference, current, mrpt::poses::CPosePDFGaussian(coarse.best, cov), again);
	return kept;
}

MatchInspection ScanMatcher::inspectLastMatch(const ScanPoints& reference,
	const ScanPoints& current, const mrpt::poses::CPose2D& sensorEstimate) const
{
	return m_lastMatchByFallback
		? m_fallback->inspectLastMatch(reference, current, sensorEstimate)
		: inspectOwnMatch(reference, current, sensorEstimate);
}

MatchInspection ScanMatcher::inspectOwnMatch(const ScanPoints& reference,
	const ScanPoints& current, const mrpt::poses::CPose2D& sensorEstimate) const
{
	MatchInspection out;
	char desc[120];
	std::snprintf(desc, sizeof(desc), "nearest neighbours at the estimate within %.1f m",
		kInspectionPairDistance);
	out.pairsDescription = desc;
	mrpt::maps::CSimplePointsMap map;
	for (const auto& p : reference.points) map.insertPoint(p.x, p.y, 0);
	if (map.empty()) return out;
	for (const auto& p : current.points)
	{
		double wx = 0, wy = 0;
		sensorEstimate.composePoint(p.x, p.y, wx, wy);
		float rx = 0, ry = 0, d2 = 0;
		map.kdTreeClosestPoint2D(static_cast<float>(wx), static_cast<float>(wy), rx, ry, d2);
		if (d2 <= kInspectionPairDistance * kInspectionPairDistance)
			out.pairs.push_back({{rx, ry}, {p.x, p.y}});
	}
	return out;
}
}  // namespace featloc
