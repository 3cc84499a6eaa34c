#pragma once
#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace featloc
{
/** Counts and timings of one run, for the console and summary.json. */
struct RunStats
{
	std::string rawlog;
	std::string estimator;
	std::string matcherClass;  //!< empty when no matcher ran
	std::string laserLabel;

	size_t entries = 0;	 //!< rawlog entries read
	size_t steps = 0;  //!< observation frames processed (= trajectory rows)
	size_t scans = 0;  //!< steps that held a 2-D scan
	std::map<std::string, size_t> scansPerLabel;  //!< every 2-D scan seen
	size_t stereoPairs = 0;	 //!< checked CObservationStereoImages
	/** Stereo landmarks ([StereoLandmarks] class): pairs processed, pairs
	 * with no map wall in view, observations on a plane, selected
	 * features, landmarks started, observations that updated the EKF. */
	size_t stereoFrames = 0, stereoFramesWithoutWall = 0, stereoObservations = 0;
	size_t stereoSelected = 0, stereoLandmarksStarted = 0, stereoUpdates = 0;
	/** Wall observations handed to the EKF (StereoWallObservation), used,
	 * and failed their own gate. */
	size_t stereoWallsObserved = 0, stereoWallsUsed = 0, stereoWallsRejected = 0;
	std::vector<double> stereoTimes;  //!< [s] extractor per pair
	std::string stereoMap;	//!< its map file
	size_t odometryReadings = 0;  //!< CObservationOdometry (format #2)
	size_t odometryActions = 0;	 //!< CActionRobotMovement2D (format #1)
	size_t stepsWithoutOdometry = 0;
	size_t stepsWithExtrapolatedOdometry = 0;  //!< [Odometry] max_extrapolation
	/** Steps without odometry that moved at the estimate's recent velocity
	 * ([Odometry] no_odometry_prior = constant_velocity). */
	size_t stepsWithVelocityPrior = 0;
	size_t landmarkObservations = 0;  //!< CObservationBearingRange read
	/** Observations (and actions) of classes no handler takes, per class. */
	std::map<std::string, size_t> ignoredObservations;
	size_t landmarksInMap = 0;	//!< the estimator's landmarks at the end
	size_t invalidatedBeams = 0;

	size_t keyframes = 0;  //!< reference scans used by the matcher
	size_t matchesAttempted = 0;
	size_t matchFailures = 0;  //!< matcher reported failure
	/** The failures by MatchResult::failureKind (ambiguous, no_overlap,
	 * guess_gate, matcher, too_few_points). */
	std::map<std::string, size_t> matchFailuresByKind;
	/** Successful matches flagged ambiguous, used with an inflated
	 * covariance (MatchResult::ambiguous). */
	size_t ambiguousMatches = 0;
	/** Successful matches whose guess-gate rejection the scans overruled
	 * (MatchResult::guessGateOverruled). */
	size_t guessGateOverruled = 0;
	/** Matches where the matcher took its own fallback
	 * (MatchResult::matcherFallback). */
	size_t matcherFallbacks = 0;
	/** Matches that dropped segments of the current scan as moved by their
	 * residuals (MatchResult::segmentsDroppedByResiduals > 0), and how
	 * many segments in all. */
	size_t matchesWithSegmentsDroppedByResiduals = 0;
	size_t segmentsDroppedByResiduals = 0;
	/** Matches the fallback matcher made after the configured one failed
	 * (MatchResult::primaryFailure), and how many of those succeeded. */
	size_t fallbackMatcherMatches = 0;
	size_t fallbackMatcherSuccesses = 0;
	/** Matches whose coarse search was skipped: the points confirmed the
	 * iterations from the guess (MatchResult::confirmedShare). */
	size_t coarseSearchSkipped = 0;
	/** Matches the share confirmed but a slid pose fit as well, so the
	 * search ran (MatchResult::confirmationSlid). */
	size_t coarseConfirmationsSlid = 0;
	/** Matches whose current scan's readings sat on a range lattice
	 * (MatchResult::rangeLatticeStep), its steps [m], and how many of
	 * those the matcher put back on their surfaces (dequantize_ranges). */
	size_t rangeLatticeMatches = 0;
	std::vector<double> rangeLatticeSteps;
	size_t dequantizedMatches = 0;
	/** Matches that kept the guess along the one direction their points
	 * left free (MatchResult::guessKeptAlongFreeDirection; also counted in
	 * ambiguousMatches). */
	size_t guessKeptAlongFreeDirection = 0;
	size_t fallbacks = 0;  //!< steps where the estimator used odometry
	/** A few failure examples: "scan 123: reason". */
	std::vector<std::string> failureExamples;
	/** A few examples of successful matches the estimator did not use
	 * (e.g. the EKF's gate): "scan 123: reason". */
	std::vector<std::string> rejectionExamples;
	std::vector<double> matchTimes;	 //!< [s] per match
	/** Localization in a known map ([Localization] map): the map (its
	 * description), scans matched against it, matches used by the
	 * estimator, failed, and rejected by its gate (with examples). */
	std::string localizationMap;
	std::string localizationMapFile;  //!< its path, as read
	size_t mapMatchesAttempted = 0, mapMatchesUsed = 0, mapMatchFailures = 0,
		   mapMatchesRejected = 0;
	std::map<std::string, size_t> mapMatchFailuresByKind;
	std::vector<std::string> mapRejectionExamples;
	std::vector<double> mapMatchTimes;	//!< [s] per map match
	/** "found at scan 3 (entry #7): at (...)", "lost at scan 90 ...": when
	 * the robot was found in the map, lost, and found again. */
	std::vector<std::string> localizationEvents;
	size_t globalSearches = 0;
	/** With `initial_pose = global`: the log time [s since the epoch] of
	 * the step where the robot was first found (before it the estimate is
	 * not in the map's frame); negative while not found. */
	double firstFoundTime = -1;
	bool globalStart = false;
	std::vector<double> globalSearchTimes;	//!< [s] per global search
	std::vector<unsigned int> matchIterations;
	/** [s] per step after the first: the estimator's own work (prediction,
	 * fusion, landmarks), the matcher's time excluded. */
	std::vector<double> estimatorTimes;

	double wallTime = 0;  //!< [s] whole run, reading and writing included
	/** [s] from the first processed step's time to the last's. */
	double logSeconds = 0;
	/** Factor the odometry covariance was inflated by after checking it
	 * against the matches ([Odometry] covariance_check; 1: not inflated). */
	double odometryCovarianceScale = 1;
	/** The odometry direction offset the estimator learnt and its sigma
	 * [deg] (EkfEstimator, [Ekf] odometry_direction_sigma_DEG > 0). */
	std::optional<std::pair<double, double>> odometryDirectionOffsetDeg;
	bool ok = true;
	/** Stopped early by SIGINT/SIGTERM (the outputs hold what was read). */
	bool interrupted = false;
	std::string error;	//!< when !ok
};
}  // namespace featloc
