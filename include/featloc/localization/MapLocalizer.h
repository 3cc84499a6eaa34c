#pragma once
#include <mrpt/poses/CPosePDFGaussian.h>

#include <memory>
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
 *   the robot is lost and the global search starts.
 * - Searching (from the start with `[Pipeline] initial_pose = global`, or
 *   once lost): GlobalMapSearch over the whole map for every scan. A
 *   hypothesis is the best pose of a scan; the next scan's best confirms it
 *   when it lies where the odometry since then moves the hypothesis
 *   (within confirm_distance / confirm_angle). The robot is found when
 *   global_confirm_scans scans in a row agree, each scoring at least
 *   global_min_score, and the last one's best rival (a pose further than
 *   the search's distinct distance) scores below global_rival_ratio x the
 *   best: a corridor's two ends, or two identical rooms, never confirm
 *   until the robot sees what tells them apart. The estimator then restarts
 *   at the found pose, refined by a map match. */
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
	const LocalizationOptions& options() const { return m_options; }

	/** Poses further apart than this are different hypotheses. */
	static constexpr double kConfirmDistance = 0.2;	 //!< [m]
	static constexpr double kConfirmAngle = 0.08726646259971647;  //!< [rad] (5 deg)

   private:
	void search(const EstimationStep& step, PoseEstimator& estimator, Outcome& out);
	void track(const EstimationStep& step, PoseEstimator& estimator, Outcome& out);

	std::shared_ptr<const LocalizationMap> m_map;
	LocalizationOptions m_options;
	MapScanTracker m_tracker;
	std::unique_ptr<GlobalMapSearch> m_global;	// built on the first search
	bool m_tracking;
	unsigned int m_misses = 0;	// scans in a row without a usable map match
	// Searching: the last scan's hypothesis, the odometry since that scan,
	// and how many scans in a row agree with it.
	std::optional<mrpt::poses::CPose2D> m_hypothesis;
	mrpt::poses::CPose2D m_odometrySince;
	unsigned int m_streak = 0;
};
}  // namespace featloc
