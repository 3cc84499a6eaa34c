#pragma once
#include <mrpt/poses/CPosePDFGaussian.h>

#include <deque>
#include <optional>
#include <string>
#include <vector>

#include "featloc/io/InputOptions.h"
#include "featloc/io/RawlogEntry.h"
#include "featloc/odometry/OdometryOptions.h"
#include "featloc/odometry/OdometryTimeline.h"
#include "featloc/pipeline/ScanStep.h"
#include "featloc/scan/LaserScanSelector.h"

namespace featloc
{
/** Turns rawlog entries into ScanSteps: the selected laser scans in time
 * order, each with the odometry motion since the previous one.
 *
 * Odometry, either format:
 * - Format #1: CActionRobotMovement2D increments between sensory frames are
 *   composed (means and covariances, on SE(2)) until the next scan.
 * - Format #2: CObservationOdometry absolute readings are interpolated at
 *   each scan's time (OdometryTimeline), so a scan waits until a reading at
 *   or after its time arrives (or the log ends, or a later scan shows the
 *   odometry stopped). The increment's covariance comes from the
 *   [Odometry] model.
 *
 * Landmarks: the points of CObservationBearingRange observations (range,
 * bearing; pitch ignored) go, in the robot frame with their covariances,
 * into the next selected scan's step and are applied at that scan's time
 * (exact when the landmark sensor fires with the laser, as featloc-sim's
 * does; otherwise the robot's motion in between is an unmodelled error).
 * A log without laser scans gives no steps, so no landmark updates.
 *
 * Scan times must strictly increase; a repeat or a step back is an
 * InputError naming the entries (carmen2rawlog in MRPT 2.5.8 stamps every
 * scan with the same time). */
class ScanStepAssembler
{
   public:
	/** A selected scan inside the entry just pushed. */
	struct SelectedScan
	{
		size_t scanIndex;
		const mrpt::obs::CObservation* source;
	};

	ScanStepAssembler(
		const InputOptions& input, const OdometryOptions& odometry,
		std::string rawlogName);

	/** Consumes one entry. `selected` gets the scans of this entry that
	 * will become steps; `ready` gets the steps that can be processed now
	 * (possibly of earlier entries). */
	void push(
		const RawlogEntry& entry, std::vector<SelectedScan>& selected,
		std::vector<ScanStep>& ready);

	/** End of the log: every pending scan becomes a step. */
	void finish(std::vector<ScanStep>& ready);

	/** True once max_scans scans were selected (reading can stop). */
	bool full() const;

	const LaserScanSelector& selector() const { return m_selector; }
	size_t odometryReadings() const { return m_odometryReadings; }
	size_t odometryActions() const { return m_actions; }
	size_t stepsWithoutOdometry() const { return m_stepsWithoutOdometry; }
	size_t landmarkObservations() const { return m_landmarkObservations; }

   private:
	struct Pending
	{
		ScanStep step;
		bool fromActions = false;  //!< odometry came from format #1 actions
	};

	void onObservation(
		const mrpt::obs::CObservation::Ptr& obs, size_t entryIndex,
		std::vector<SelectedScan>& selected);
	void addLandmarks(
		const mrpt::obs::CObservationBearingRange& obs, const std::string& where);
	void onAction(const mrpt::serialization::CSerializable::Ptr& action);
	void release(bool endOfLog, std::vector<ScanStep>& ready);
	void completeFromTimeline(ScanStep& step);
	mrpt::poses::CPosePDFGaussian noOdometryPrior() const;
	mrpt::poses::CPosePDFGaussian modelIncrement(
		const mrpt::poses::CPose2D& increment) const;

	InputOptions m_input;
	OdometryOptions m_odo;
	std::string m_rawlogName;
	LaserScanSelector m_selector;
	OdometryTimeline m_timeline;
	std::deque<Pending> m_pending;

	size_t m_nextScanIndex = 0;
	std::optional<mrpt::Clock::time_point> m_lastScanTime;
	size_t m_lastScanEntry = 0;
	std::optional<mrpt::Clock::time_point> m_lastOdometryTime;

	// Format #1: composed action increments since the last scan.
	bool m_haveActions = false;
	mrpt::poses::CPosePDFGaussian m_actionSum;

	// Format #2: odometry pose at the previous released scan.
	std::optional<mrpt::poses::CPose2D> m_prevScanOdometry;

	// Landmark observations since the last selected scan.
	std::vector<LandmarkObservation> m_landmarks;

	size_t m_odometryReadings = 0, m_actions = 0, m_stepsWithoutOdometry = 0;
	size_t m_landmarkObservations = 0;
};
}  // namespace featloc
