#pragma once
#include <mrpt/config/CLoadableOptions.h>
#include <mrpt/poses/CPosePDFGaussian.h>

#include <memory>
#include <string>
#include <vector>

#include "featloc/matchers/CorrelationTables.h"
#include "featloc/matchers/ReferenceTables.h"
#include "featloc/scan/PointNoiseEstimator.h"
#include "featloc/scan/ScanPoints.h"
#include "featloc/scan/ScanSegment.h"

namespace featloc
{
/** The wide-basin stage in front of every featloc matcher: Olson's
 * multi-resolution correlative scan matching ("Real-time correlative scan
 * matching", ICRA 2009, sections III-IV), as Cartographer's and Karto's
 * front ends use it.
 *
 * The reference scan becomes a lookup table: each cell holds
 * exp(-d^2 / 2 sigma_hit^2), d the distance to the reference surface (its
 * points joined where consecutive; distances within 5 widths of the
 * scores, CorrelationTables::buildNear). A pose's
 * score is the mean table value under the current scan's points placed by
 * that pose: the share of the scan that lies on the reference. Every pose of
 * the guess's 3-sigma window is scored, on a grid of `resolution` in
 * translation and of one cell's motion at the far points in rotation, by
 * branch and bound: low-resolution tables holding the maximum over each
 * block of 2^L x 2^L cells bound every pose of a block, and blocks are
 * opened best bound first, each split in four.
 *
 * A scan that is nowhere on the reference has too little overlap: the
 * search fails. The search also keeps going down to contender_ratio x the
 * best score, to find the contenders: poses further than coarse_distinct_xy
 * or coarse_distinct_yaw_DEG from the best (featloc-bench's gross error).
 * Once the matcher has refined the best, ambiguity() compares its estimate
 * with them on a sharp score (sigma of about the range noise, every
 * current point), point by point: a
 * distinct solution that the points do not clearly reject makes the match
 * ambiguous,
 * and it is reported as a failure: a flagged failure is better than a
 * confident wrong answer. The sharp score is what decides because the
 * search's own score is smooth by design (its wide sigma makes the basin)
 * and cannot tell a corridor's stretches apart that the matcher can. */
class CorrelativeScanSearch
{
   public:
	struct Options : public mrpt::config::CLoadableOptions
	{
		/** coarse_search: on by default for featloc's matchers (PCM, IDC,
		 * CF-IDC), whose "as published" variants switch it off; off for
		 * IcpMatcher (MRPT's ICP, the peer). */
		bool enabled = true;
		double windowSigmas = 3.0;	//!< half-window in sigmas of the guess
		/** The half-window is at least this: odometry's covariance can be
		 * far too small (a 5.7 deg turn error under a 1 deg sigma on MRPT's
		 * simulated log), and a search that misses the truth is worse than
		 * none. */
		double minWindowXY = 0.20;	//!< [m]
		double minWindowYaw = 0.13962634015954636;	//!< [rad] (8 deg)
		double maxWindowXY = 0.60;	//!< [m] half-window at most this
		double maxWindowYaw = 0.4363323129985824;  //!< [rad] (25 deg)
		double resolution = 0.03;  //!< [m] lookup cell and translation step
		double hitSigma = 0.05;	 //!< [m] width of the table around the surface
		unsigned int maxPoints = 150;  //!< current points scored (evenly picked)
		double minScore = 0.25;	 //!< fail below this share of points on the reference
		double contenderRatio = 0.90;  //!< poses scoring this x the best are contenders
		double ambiguityZ = 1.0;  //!< ambiguous unless the points favour the estimate by this z (0: off)
		/** What an ambiguous match becomes: "inflate" (its covariance grows
		 * to cover every rival, and it is used, flagged) or "fail". */
		std::string onAmbiguity = "inflate";
		/** A guess-gate rejection is overruled when a search of the widest
		 * window around the guess finds the estimate, unambiguous, and the
		 * scan's objects (overruleObjectSpan) favour it over the guess by
		 * this z (ScanMatcher::arbitrateGuessGate; 0: off; needs
		 * ambiguityZ > 0).
		 * Runs whether or not `enabled`. */
		double overruleGuessZ = 3.0;
		/** [m] The arbiter's evidence counts objects, not points: the
		 * current points are grouped into runs within this span
		 * (objectGroups()), and each run is one witness (0: every point
		 * is one, as before the twenty-third session). */
		double overruleObjectSpan = 0.3;
		double sharpSigma = 0.02;  //!< [m] width of the sharp score, at least (else 2x the scan's scatter)
		/** Solutions further apart than this in translation or rotation are
		 * distinct: the silent-gross-error thresholds of featloc-bench. */
		double distinctXY = 0.10;  //!< [m]
		double distinctYaw = 0.03490658503988659;  //!< [rad] (2 deg)
		/** The matcher's iterations run from each rival too
		 * (ScanMatcher::matchFromCoarseSearch): a rival they bring back to
		 * the estimate (not distinct from it) counts as a pose on the slope
		 * of the estimate's own minimum, where the search's coarse score is
		 * flat (a turn about a round hall's centre), and no ambiguity. Off
		 * by default: on the real logs the iterations also brought back
		 * rivals that the points favoured, and flagged matches 11-25 cm off
		 * the reference poses became silent ones (orebro's silent pairs
		 * 0.4% -> 2.1%; doc/benchmarks.md, "Issue 15, thirty-third
		 * session"). false: every rival the points do not reject counts. */
		bool refineRivals = false;
		/** The search is skipped when the matcher's iterations from the
		 * guess succeed at a pose that puts at least this share of the
		 * current points within confirmDistance of a reference point
		 * (ReferenceOverlap, ScanMatcher::matchConfirmedFromGuess; 0: the
		 * search always runs; IcpMatcher: 0). */
		double confirmShare = 0.85;
		double confirmDistance = 0.05;	//!< [m]
		/** The confirmation must also find the estimate where the points
		 * peak along its least certain translation: if a pose slid along it
		 * puts as large a share of the points within confirmDistance, the
		 * search runs (an aisle or a corridor on a range lattice, where the
		 * iterations can stop along it with the walls' points all on the
		 * reference; an aisle's uprights, where they stop a bay off). The
		 * slid poses: 2 and 4 x confirmDistance either way, then, with
		 * confirmProbeWindow, every confirmDistance out to the edges of the
		 * window the search would cover (halfWindow). */
		bool confirmProbe = true;
		bool confirmProbeWindow = true;
		/** The probe runs only where the estimate's largest translation
		 * sigma (with confirmProbeTurn, of its motion with the turn scaled
		 * by the points' RMS range) reaches this: a match that fixes every direction to a 25th
		 * of the probe's shorter step (2 x 5 cm) has no weak direction to
		 * slide along, and the probe's four shares would cost PCM's office
		 * pairs a seventh of their time (doc/benchmarks.md, "Issue 15,
		 * nineteenth session"). 0: wherever the share confirms. */
		double confirmProbeSigma = 0.004;  //!< [m]
		/** The probe follows the estimate's least certain motion with its
		 * turn: the largest eigenvector of its covariance with the yaw
		 * scaled by the current points' RMS range (how far a turn moves
		 * them), the pose turned about that motion's centre. A round wall
		 * fixes the position but not a turn about its centre, and a round
		 * hall's 5-degree facets put a pose turned a facet about it on the
		 * reference as well as the right one (doc/benchmarks.md, "Issue
		 * 15, twenty-ninth session"). false: the least certain translation
		 * only, the heading kept. */
		bool confirmProbeTurn = true;

		void loadFromConfigFile(
			const mrpt::config::CConfigFileBase& c, const std::string& s) override;
		void saveToConfigFile(
			mrpt::config::CConfigFileBase& c, const std::string& s) const override;
	};

	struct Result
	{
		bool success = false;
		std::string failureReason;
		mrpt::poses::CPose2D best;	//!< pose of current in reference
		double bestScore = 0;  //!< share of the scored points on the reference [0-1]
		struct Contender
		{
			mrpt::poses::CPose2D pose;
			double score = 0;
		};
		/** The best poses distinct from `best` and from one another that
		 * score at least contenderRatio x bestScore, best first. */
		std::vector<Contender> contenders;
		double windowXY[2] = {0, 0}, windowYaw = 0;	 //!< half-widths searched
		double resolution = 0;	//!< [m] translation step used (cell size)
		double yawStep = 0;	 //!< [rad] rotation step
		/** Covariance to give the matcher that refines `best`: one step of
		 * the search grid as one sigma. */
		mrpt::math::CMatrixDouble33 gridCovariance() const;
	};

	Options options;

	/** The half-widths search() covers around a guess: windowSigmas of its
	 * sigmas, clamped to [min, max] windows (the widest for a covariance
	 * that is not finite). */
	struct HalfWindow
	{
		double xy[2] = {0, 0}, yaw = 0;
	};
	HalfWindow halfWindow(const mrpt::poses::CPosePDFGaussian& guess) const;

	/** Searches the window around `guess` (its mean, 3 sigma of its
	 * covariance clamped to [min, max] windows). `reference` and `current`
	 * are in their sensor frames, `guess` is current's pose in reference's. */
	Result search(const ScanPoints& reference, const ScanPoints& current,
		const mrpt::poses::CPosePDFGaussian& guess);

	struct Ambiguity
	{
		bool ambiguous = false;
		/** The solutions the points do not reject, at their best grid
		 * neighbours. */
		std::vector<mrpt::poses::CPose2D> rivals;
		std::vector<std::string> reasons;  //!< one per rival
		std::string reason;	 //!< about the first rival
	};
	/** Whether `estimate` (the matcher's refinement of r.best) is
	 * ambiguous: a contender of `r` (or r.best itself), distinct from it,
	 * inside the 99% region of `guess` (the search's window covariance),
	 * and at its best grid neighbour, that the points do not reject: the
	 * paired evidence for the estimate (evidence()) is below ambiguityZ. */
	Ambiguity ambiguity(const Result& r, const mrpt::poses::CPose2D& estimate,
		const mrpt::poses::CPosePDFGaussian& guess) const;

	/** The paired evidence for pose a over pose b of the last search's
	 * current scan (evidence() of their sharp scores; both poses as given,
	 * no grid neighbour). With objectSpan > 0 the points are first grouped
	 * into objects (objectGroups()) and each object is one witness. */
	double evidenceFor(const mrpt::poses::CPose2D& a, const mrpt::poses::CPose2D& b,
		double objectSpan = 0) const;

	/** The paired evidence for a over b from their points' sharp scores:
	 * z = sum(d_i) / sqrt(sum(d_i^2)), d_i = a_i - b_i (0 when they score
	 * alike). Points on a corridor's walls score alike under both and do
	 * not count; a door frame that only a explains does.
	 * With `group` (group[i]: point i's object, consecutive points sharing
	 * one) the differences are summed per object first:
	 * z = sum_c(D_c) / sqrt(sum_c(D_c^2)), D_c the sum of d_i over object c.
	 * The points of one object (a person, a stretch of wall) are right or
	 * wrong together under a pose, so they are one witness, not many: the
	 * cluster-robust form of the variance. Empty: every point is one. */
	static double evidence(const std::vector<double>& a, const std::vector<double>& b,
		const std::vector<uint32_t>& group = {});
	/** The object of each current point of the last search: runs of
	 * consecutive points (in bearing order) within `span` of the run's first
	 * point. A person is one object; a wall is cut into stretches of
	 * `span`; a jump to a farther surface starts a new one. */
	std::vector<uint32_t> objectGroups(double span) const;

	/** Whether two poses are distinct solutions (distinctXY, distinctYaw). */
	bool distinct(const mrpt::poses::CPose2D& a, const mrpt::poses::CPose2D& b) const;

	/** From now on this search and `other` keep what they build for a
	 * reference (ReferenceTables) in one pool: a search finds the other's
	 * tables of the same reference there (and its last branch and bound,
	 * when its points, window and ratio are the same), and never rebuilds
	 * tables the other is using. A matcher shares with its fallback. */
	void shareTablesWith(CorrelativeScanSearch& other);

   private:
	/** The tables of `reference`, with levels up to blocks as wide as a
	 * window of +-halfWindowXY. */
	void buildTables(const ScanPoints& reference, double halfWindowXY);
	void pickPoints(const ScanPoints& current);
	/** Every grid pose of r's window whose score reaches contenderRatio x
	 * the best (only the best when the ambiguity test is off), best first;
	 * the tables' last branch and bound's when its input was the same (it
	 * keeps this one's for the next). */
	std::vector<Result::Contender> branchAndBound(
		const mrpt::poses::CPosePDFGaussian& guess, Result& r);
	/** The grid neighbour of `o` (one step in x, y, yaw) with the best
	 * sharp score; its points' sharp scores in `scores`. */
	mrpt::poses::CPose2D bestGridNeighbour(
		const Result& r, const mrpt::poses::CPose2D& o, std::vector<double>& scores) const;
	/** Every current point's sharp score at `pose`: exp(-d^2 / 2 sigma^2),
	 * d its distance to the reference surface, sigma the larger of
	 * sharp_sigma and twice the reference's point scatter. */
	void sharpScores(const mrpt::poses::CPose2D& pose, std::vector<double>& out) const;

	/** Makes m_ref the pool's tables of `reference` at `top` with
	 * `options` and returns true; where the pool has none, makes it tables
	 * no other search uses, to be built, and returns false. */
	bool useTablesOf(
		const ScanPoints& reference, int top, const ReferenceTables::BuildOptions& options);

	using TablesPool = std::vector<std::shared_ptr<ReferenceTables>>;
	std::shared_ptr<TablesPool> m_pool = std::make_shared<TablesPool>();
	// The tables this search uses, one of the pool's (null before the
	// first search). Held here, no other search rebuilds them.
	std::shared_ptr<ReferenceTables> m_ref;
	PointNoiseEstimator m_noise;
	std::vector<double> m_px, m_py;	 // the scored current points
	std::vector<double> m_allX, m_allY;	 // every current point (sharp score)
};
}  // namespace featloc
