#pragma once
#include <mrpt/poses/CPosePDFGaussian.h>

#include <deque>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "featloc/estimators/EstimationStep.h"
#include "featloc/io/InputOptions.h"
#include "featloc/io/RawlogEntry.h"
#include "featloc/odometry/OdometryOptions.h"
#include "featloc/odometry/OdometryTimeline.h"
#include "featloc/output/StepSource.h"
#include "featloc/pipeline/ObservationHandler.h"
#include "featloc/scan/LaserScanSelector.h"

namespace featloc
{
class LaserScanHandler;
class BearingRangeHandler;

/** Turns source entries into EstimationSteps: observation frames in time
 * order, each with the odometry motion since the previous one.
 *
 * Observations go to the ObservationHandler registered for their class
 * (2-D scan, range-bearing landmarks, odometry reading; more with
 * addHandler); a class nobody handles is counted (ignoredObservations) and
 * skipped.
 *
 * Frames: the observations of a sensory frame make one step (MRPT's
 * sensory frame is one robot pose; in format #1 the action before it is
 * the motion to it), unless the log gives odometry readings
 * (CObservationOdometry), which can be interpolated at each observation's
 * own time: then, as in format #2, observations that share a timestamp
 * make one step, each step at its own time. A step stays open until an observation with a later time (or the
 * next action or frame) arrives.
 *
 * Odometry, either format:
 * - Format #1: CActionRobotMovement2D increments are composed (means and
 *   covariances, on SE(2)) until the next step.
 * - Format #2: CObservationOdometry absolute readings are interpolated at
 *   each step's time (OdometryTimeline), so a step waits until a reading at
 *   or after its time arrives (or the log ends, or a later step shows the
 *   odometry stopped). The increment's covariance comes from the
 *   [Odometry] model.
 *
 * Scan times must strictly increase (carmen2rawlog in MRPT 2.5.8 stamps
 * every scan with the same time: the error says so); step times must not
 * go back. */
class StepAssembler
{
   public:
	StepAssembler(
		const InputOptions& input, const OdometryOptions& odometry, std::string sourceName);
	~StepAssembler();

	/** A handler for another observation class (before the first push). */
	void addHandler(ObservationHandler::Ptr handler);

	/** Consumes one entry. `used` gets the observations of this entry that
	 * went into steps; `ready` gets the steps that can be processed now
	 * (possibly of earlier entries). */
	void push(
		const RawlogEntry& entry, std::vector<StepSource>& used,
		std::vector<EstimationStep>& ready);

	/** End of the log: every pending step is released. */
	void finish(std::vector<EstimationStep>& ready);

	/** True once max_scans scans were taken (reading can stop; no step
	 * opens after that). */
	bool full() const;

	const LaserScanSelector& selector() const;
	size_t odometryReadings() const { return m_odometryReadings; }
	size_t odometryActions() const { return m_actions; }
	size_t stepsWithoutOdometry() const { return m_stepsWithoutOdometry; }
	/** Steps whose odometry was extrapolated ([Odometry] max_extrapolation). */
	size_t stepsWithExtrapolatedOdometry() const { return m_stepsExtrapolated; }
	size_t landmarkObservations() const;
	/** Observations of classes no handler takes, per class name. */
	const std::map<std::string, size_t>& ignoredObservations() const { return m_ignored; }
	/** Every observation and action read, per class name. */
	const std::map<std::string, size_t>& objectsPerClass() const { return m_perClass; }

   private:
	struct Pending
	{
		EstimationStep step;
		bool fromActions = false;  //!< odometry came from format #1 actions
		/** The last of those actions' timestamp (none: the log gives none). */
		std::optional<mrpt::Clock::time_point> actionTime;
	};

	void onObservation(
		const mrpt::obs::CObservation::Ptr& obs, size_t entryIndex, bool sameFrame,
		std::vector<StepSource>& used);
	void onOdometryReading(
		mrpt::Clock::time_point t, const mrpt::poses::CPose2D& pose, const std::string& where);
	void checkScanTime(mrpt::Clock::time_point t, size_t entryIndex, const std::string& where);
	void openFrame(mrpt::Clock::time_point t, size_t entryIndex, const std::string& where);
	void closeFrame();
	void onAction(const mrpt::serialization::CSerializable::Ptr& action);
	void release(bool endOfLog, std::vector<EstimationStep>& ready);
	/** A step at t can go without a reading after it: none has come yet,
	 * or [Odometry] max_extrapolation allows t from the readings so far. */
	bool needsNoLaterReading(mrpt::Clock::time_point t) const;
	void completeFromTimeline(EstimationStep& step);
	mrpt::poses::CPosePDFGaussian noOdometryPrior() const;

	InputOptions m_input;
	OdometryOptions m_odo;
	std::string m_sourceName;
	std::vector<ObservationHandler::Ptr> m_handlers;
	LaserScanHandler* m_laser = nullptr;
	BearingRangeHandler* m_bearingRange = nullptr;
	OdometryTimeline m_timeline;

	std::optional<Pending> m_open;	//!< the frame still collecting observations
	std::deque<Pending> m_pending;	//!< closed frames waiting for odometry

	size_t m_nextStepIndex = 0, m_nextScanIndex = 0;
	std::optional<mrpt::Clock::time_point> m_lastScanTime, m_lastStepTime;
	size_t m_lastScanEntry = 0, m_lastStepEntry = 0;
	std::optional<mrpt::Clock::time_point> m_lastOdometryTime;

	// Format #1: composed action increments since the last step.
	bool m_haveActions = false;
	mrpt::poses::CPosePDFGaussian m_actionSum;
	std::optional<mrpt::Clock::time_point> m_lastActionTime;  //!< of the last of them

	// Format #2: odometry pose at the previous released step.
	std::optional<mrpt::poses::CPose2D> m_prevStepOdometry;

	size_t m_odometryReadings = 0, m_actions = 0, m_stepsWithoutOdometry = 0,
		m_stepsExtrapolated = 0;
	std::map<std::string, size_t> m_ignored, m_perClass;
};
}  // namespace featloc
