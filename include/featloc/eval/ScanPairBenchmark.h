#pragma once
#include <Eigen/Core>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "featloc/eval/ScanPairCramerRaoBound.h"
#include "featloc/matchers/ScanMatcher.h"

namespace featloc
{
/** Two scans and the true robot motion between them. */
struct ScanPairSample
{
	mrpt::obs::CObservation2DRangeScan::Ptr reference, current;
	mrpt::poses::CPose2D truth;	 //!< current robot pose in the reference's
	/** The pair's Cramer-Rao bound, where the scene's true surfaces are
	 * known (featloc-bench --world). Not used with Options::applyMotion
	 * (the moved scan's relative pose is another one). */
	std::optional<ScanPairCramerRaoBound> bound;
	/** Where the world is known (featloc-bench --world): the current
	 * scan's beams on something that moved since the reference scan
	 * (MovedSurfaceBeams: a person, a cart, a door), ascending; whether the
	 * matchers keep them is counted. */
	std::vector<uint32_t> movedBeams;
	bool movedKnown = false;
};

/** The scan-pair protocols of the papers.
 *
 * Borges & Aldon (section 5): each matcher gets every pair with the
 * initial estimate t0 = t + e_t, w0 = w + e_w, the errors uniform in
 * [-perturbXY, perturbXY] per axis and [-perturbYaw, perturbYaw] (or
 * Gaussian with those sigmas).
 *
 * Nunez et al. (CF-IDC, section IV.B), with applyMotion: the current scan
 * is moved by a random motion (mean 1 m and 15 deg, sd 50 mm and 5 deg in
 * the paper: appliedMotion plus the Gaussian draw) and every matcher starts
 * from the mean motion.
 *
 * The same draw for every matcher. Every pair counts: a failed match counts
 * with the error of its guess, which is what the pipeline then uses.
 * Reported: the mean absolute errors in t_x, t_y and w (both papers'
 * metric), mean / median / p95 of the translation and rotation errors, the
 * flagged pairs (failures by kind, and successes flagged ambiguous, counted
 * with their estimate's error) and the silent gross errors (another
 * success off by more than grossTrans or grossYaw), time and iterations per match, and the
 * NEES of the returned covariances over the successes. Matchers run interleaved pair by pair so that
 * timings share the machine's state. */
class ScanPairBenchmark
{
   public:
	struct Options
	{
		double perturbXY = 0.3;	 //!< [m]
		double perturbYaw = 0.17453292519943295;  //!< [rad] (10 deg)
		std::string perturbation = "uniform";  //!< uniform | gaussian
		unsigned int seed = 1;
		/** Nunez et al.'s protocol instead: the current scan is moved by a
		 * random motion, appliedMotion plus the draw above, and every
		 * matcher starts from appliedMotion (the mean). */
		bool applyMotion = false;
		mrpt::poses::CPose2D appliedMotion;
		/** A success off by more than this is a silent gross error. */
		double grossTrans = 0.10;  //!< [m]
		double grossYaw = 0.03490658503988659;	//!< [rad] (2 deg)
	};
	/** One pair's outcome for one matcher (featloc-bench --pairs). */
	struct PairOutcome
	{
		enum class Status : uint8_t
		{
			Used,  //!< a success, not flagged
			Ambiguous,	//!< flagged ambiguous, used with an inflated covariance
			Failed	//!< the guess is what the pipeline uses
		};
		Status status = Status::Used;
		/** What the pipeline uses (the estimate, or the guess on a failure)
		 * minus the truth, in the reference's robot frame (x, y, yaw). */
		Eigen::Vector3d error = Eigen::Vector3d::Zero();
		/** The estimate's covariance (the guess's on a failure). */
		Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
		/** Why it failed, or why it is ambiguous; empty when used. */
		std::string reason;
	};
	struct Result
	{
		std::string matcher;
		/** Per pair, in the pairs' order (one entry per pair). */
		std::vector<PairOutcome> outcomes;
		size_t pairs = 0;
		size_t failures = 0;  //!< flagged: the matcher said it failed
		std::map<std::string, size_t> failuresByKind;  //!< MatchResult::failureKind
		/** Successes the matcher flagged ambiguous and used with an inflated
		 * covariance (MatchResult::ambiguous): flagged, never silent. */
		size_t ambiguousUsed = 0;
		size_t matcherFallbacks = 0;  //!< the matcher took its own fallback (MatchResult)
		/** Pairs where the matcher dropped segments as moved by their
		 * residuals (MatchResult::segmentsDroppedByResiduals). */
		size_t segmentsDroppedByResiduals = 0;
		/** Pairs the fallback matcher made after the matcher failed
		 * (MatchResult::primaryFailure), and of those the successes. */
		size_t fallbackMatches = 0, fallbackSuccesses = 0;
		/** Pairs whose coarse search was skipped: the points confirmed the
		 * iterations from the guess (MatchResult::confirmedShare). */
		size_t searchSkipped = 0;
		/** Pairs the share confirmed but a slid pose fit as well, so the
		 * search ran (MatchResult::confirmationSlid). */
		size_t confirmationsSlid = 0;
		/** Pairs whose match kept the guess along the one direction its
		 * points left free (MatchResult::guessKeptAlongFreeDirection; also
		 * in ambiguousUsed). */
		size_t guessKeptAlongFreeDirection = 0;
		size_t silentGross = 0;	 //!< other successes off by > grossTrans or > grossYaw
		/** Pairs whose used pose (the estimate, or the guess after a failure)
		 * is off by > grossTrans or > grossYaw, flagged or not: how often the
		 * pipeline is handed a wrong motion. It compares matchers that flag
		 * their doubts (an ambiguous match is flagged, and often right) with
		 * one that never does, which flagged() alone cannot. */
		size_t grossUsed = 0;
		/** Over every pair (failures at the guess's error). */
		double maeX = 0, maeY = 0, maeYaw = 0;	//!< [m], [m], [rad]
		double meanTrans = 0, medianTrans = 0, p95Trans = 0;  //!< [m] |t error|
		double medianYaw = 0, p95Yaw = 0;  //!< [rad] |w error|
		double meanTime = 0, medianTime = 0;  //!< [s] per match
		double meanIterations = 0;
		double meanNees = 0;  //!< over successes (3 for a consistent covariance)
		double medianNees = 0;	//!< 2.37 for a consistent covariance
		double neesWithin95 = 0;  //!< share within chi2(3) 95% (0.95 if consistent)
		/** Over the pairs with a finite Cramer-Rao bound (ScanPairSample::
		 * bound; every pair counts, failures at the guess's error): the
		 * matcher's mean |t| and |w| errors and the bound's, side by side. */
		size_t boundedPairs = 0;
		double boundedMeanTrans = 0, boundedMeanYaw = 0;  //!< [m], [rad] the matcher's
		double boundMeanTrans = 0, boundMeanYaw = 0;  //!< [m], [rad] the bound's E|t|, E|w|
		/** Over the pairs whose moved beams are known, for matchers that
		 * report the current scan's parts (MatchInspection: CF-IDC's
		 * segments, PCM's features): the current points on things that
		 * moved since the reference scan and on the others that fell in
		 * some part, and how many of each the match kept (after every
		 * gate). */
		size_t movedSeen = 0, movedKept = 0, stillSeen = 0, stillKept = 0;
		std::vector<std::string> failureExamples, silentGrossExamples;
		size_t flagged() const { return failures + ambiguousUsed; }
		/** Share of pairs neither flagged nor grossly wrong. */
		double successRate() const
		{
			return pairs ? static_cast<double>(pairs - flagged() - silentGross) /
					static_cast<double>(pairs)
						 : 0.0;
		}
	};

	/** Called after each pair with the number of pairs done so far. */
	using Progress = std::function<void(size_t done)>;

	static std::vector<Result> run(
		const std::vector<ScanPairSample>& pairs,
		const std::vector<ScanMatcher::Ptr>& matchers, const Options& options,
		const Progress& progress = {});
};
}  // namespace featloc
