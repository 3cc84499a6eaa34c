#pragma once
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPosePDFGaussian.h>

#include <memory>
#include <deque>
#include <optional>
#include <string>

#include "featloc/estimators/EstimationStep.h"
#include "featloc/estimators/PoseEstimator.h"
#include "featloc/localization/GlobalMapSearch.h"
#include "featloc/localization/MapScanTracker.h"

namespace featloc
{
/** Localization in a known map, scan by scan: tracking while the pose is
 * known, global localization while it is not, and the switch between the
 * two (issue "Localization in a known map", items 2 and 3).
 *
 * - Tracking: MapScanTracker matches the scan against the map around the
 *   estimate and the estimator fuses it as an absolute pose. When
 *   lost_after_scans scans in a row give no usable map match (failed, or
 *   rejected by the gate: a kidnapped robot, a map that no longer fits),
 *   the map is asked: if the scan, put back on the map around the
 *   estimate (GlobalMapSearch::refine), scores at least global_min_score
 *   and about as well as the best place anywhere in the map, the robot is
 *   where the estimate says and only the map matches' covariance is too
 *   small; otherwise it is lost and the global search starts.
 * - Searching (from the start with `[Pipeline] initial_pose = global`, or
 *   once lost): the scans since the search began (up to kMaxWindow, with
 *   the odometry between them) and hypotheses of the robot's pose, each
 *   scored on every one of those scans. Each new scan moves every
 *   hypothesis by the odometry and puts it back on the map by a small
 *   sharp correlative search (+-kTrackXY, +-kTrackYaw: GlobalMapSearch::
 *   refine), which scores it. The global search over the whole map then
 *   adds its best pose and its best rival elsewhere where no hypothesis
 *   is, and a new hypothesis is carried back through the odometry and
 *   scored on the earlier scans too, so that every hypothesis is judged on
 *   the same scans. Hypotheses the map pulls to one place merge; one that
 *   scores below global_min_score on the current scan is dropped. The
 *   robot is found at the hypothesis H with the highest total when H
 *   scored at least global_min_score on each of the last
 *   global_confirm_scans scans and its scores exceed every other
 *   hypothesis's by global_min_evidence in total over the window (each
 *   scan's score difference is a share of its points that H explains and
 *   the other does not), or its log-likelihood over the window
 *   (Placement::logLikelihood) exceeds every other's by
 *   global_min_log_evidence: the scans must prefer H, not merely allow it.
 *   The share of points weighs every point alike and moves slowly where
 *   look-alike rooms differ in a few points; the log-likelihood makes those
 *   few points decisive when they fit one room within centimetres and miss
 *   the other by decimetres. A corridor's two ends or two identical rooms
 *   score alike on both and do not confirm until the robot sees what tells
 *   them apart.
 *   The estimator then restarts at H, refined by a map match. */
class MapLocalizer
{
   public:
	MapLocalizer(std::shared_ptr<const LocalizationMap> map, ScanMatcher::Ptr matcher,
		LocalizationOptions options, bool startSearching);

	struct Outcome
	{
		/** A map match ran (tracking): its result, whether the estimator
		 * used it and why not. */
		std::optional<MapScanTracker::Result> mapMatch;
		bool used = false;
		std::string reason;
		/** A global search ran (searching). */
		std::optional<GlobalMapSearch::Result> global;
		/** "found", "lost" or empty; `event` says what and where. */
		std::string event, message;
	};
	/** The step after the estimator processed it. On "found" the estimator
	 * has been restarted at the found pose (the caller starts a new
	 * keyframe there). */
	Outcome process(const EstimationStep& step, PoseEstimator& estimator);

	bool tracking() const { return m_tracking; }
	const LocalizationMap& map() const { return *m_map; }
	/** The matcher of scans against the map. */
	const ScanMatcher& mapMatcher() const { return m_tracker.matcher(); }
	const LocalizationOptions& options() const { return m_options; }

	/** A hypothesis moved by odometry is searched for within this of where
	 * the odometry puts it. */
	static constexpr double kTrackXY = 0.25;  //!< [m]
	static constexpr double kTrackYaw = 0.13962634015954636;  //!< [rad] (8 deg)
	/** Poses closer than this are one hypothesis. */
	static constexpr double kSameXY = 0.3;	//!< [m]
	static constexpr double kSameYaw = 0.17453292519943295;	 //!< [rad] (10 deg)
	static constexpr size_t kMaxHypotheses = 30;
	/** Scans of a search kept to judge hypotheses on. */
	static constexpr size_t kMaxWindow = 40;
	/** Placement::logLikelihood's share of stray returns (people, clutter
	 * the map lacks) and a seen-through beam's likelihood. */
	static constexpr double kStray = 0.1;
	static constexpr double kThrough = 0.01;
	/** A found hypothesis's map match is not used when the scan's
	 * log-likelihood at the hypothesis exceeds it there by more than this
	 * [nats] (the robot is found at the hypothesis). 50, global_min_log_evidence's
	 * default: a lead that would tell two places apart. Chosen on the
	 * calibration starts (office and lab, seeds 1-100, 200 found events):
	 * 6 map matches not used, the found pose's mean error unchanged
	 * (36.3 -> 36.4 mm), its largest 71.7 -> 57.3 mm; at 0 (the better of
	 * the two on the map) 121 not used and 41.2 mm: the hypothesis, put on
	 * the map's 5 cm cells by the same likelihood, is favoured by it. */
	static constexpr double kRefinementLead = 50;

   private:
	void search(const EstimationStep& step, PoseEstimator& estimator, Outcome& out);
	/** Builds m_global on first use (its tables cost a fraction of a
	 * second: runs that never search do not pay). */
	void globalSearch();
	void track(const EstimationStep& step, PoseEstimator& estimator, Outcome& out);

	std::shared_ptr<const LocalizationMap> m_map;
	LocalizationOptions m_options;
	MapScanTracker m_tracker;
	std::unique_ptr<GlobalMapSearch> m_global;	// built on the first search
	bool m_tracking;
	unsigned int m_misses = 0;	// scans in a row without a usable map match
	// Searching: the scans since the search began, each with the odometry
	// from the previous one; the hypotheses, scored on each of them; the
	// odometry since the last scan.
	struct WindowScan
	{
		mrpt::obs::CObservation2DRangeScan::Ptr scan;
		mrpt::poses::CPose2D odometryFromPrevious;
	};
	std::deque<WindowScan> m_window;
	/** `around` put on the map by GlobalMapSearch::refine, and its score
	 * there less the share of the scan's beams that see through the map
	 * there (LocalizationMap::shareSeenThrough): the end points' score alone
	 * counts against a place what its map lacks (a desk the robot sees
	 * where the map has none) but not what it has and the robot does not
	 * see (a desk the beams pass through); two rooms that differ by a desk
	 * differ twice as much with both. */
	struct Placement
	{
		mrpt::poses::CPose2D pose;
		double score = 0;
		/** The scan's log-likelihood there: the sum over its valid beams of
		 * log(kStray + (1 - kStray) hit) (GlobalMapSearch::beamHits), a
		 * beam seen through the map log(kThrough): a likelihood field with
		 * a share of stray returns, as MRPT's pf-localization scores its
		 * particles, with beams through walls all but ruled out. */
		double logLikelihood = 0;
	};
	Placement placed(
		const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::poses::CPose2D& around) const;
	/** Placement::logLikelihood of the scan at `pose` exactly, and which of
	 * its beams see through the map there. */
	double logLikelihoodAt(const mrpt::obs::CObservation2DRangeScan& scan,
		const mrpt::poses::CPose2D& pose, std::vector<bool>& through) const;
	struct Hypothesis
	{
		mrpt::poses::CPose2D pose;	// at the last scan
		std::deque<Placement> scans;  // one per window scan, oldest first
		double total() const;  // of the scans' scores
		double totalLogLikelihood() const;
	};
	std::vector<Hypothesis> m_hypotheses;
	mrpt::poses::CPose2D m_odometrySince;
	/** A hypothesis made at the last scan at `pose`, put on the map there,
	 * carried back through the odometry and scored on every window scan. */
	Hypothesis backdated(const mrpt::poses::CPose2D& pose) const;
	/** The hypothesis that is found, or null. */
	const Hypothesis* confirmed() const;
};
}  // namespace featloc
