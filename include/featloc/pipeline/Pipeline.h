#pragma once
#include <atomic>
#include <string>
#include <vector>

#include "featloc/estimators/PoseEstimator.h"
#include "featloc/io/EntrySource.h"
#include "featloc/io/InputOptions.h"
#include "featloc/localization/MapLocalizer.h"
#include "featloc/matchers/ScanMatcher.h"
#include "featloc/odometry/ConstantVelocityPrior.h"
#include "featloc/odometry/OdometryCovarianceCheck.h"
#include "featloc/odometry/OdometryOptions.h"
#include "featloc/output/RunOutput.h"
#include "featloc/pipeline/PipelineOptions.h"
#include "featloc/pipeline/ProgressBar.h"
#include "featloc/output/RunStats.h"

namespace featloc
{
/** A run: the source's entries -> StepAssembler (observation frames in
 * time order with their odometry motion) -> scan matcher for the steps
 * that hold a scan (reference scan, this scan, odometry as the initial
 * guess) -> estimator -> outputs.
 *
 * The reference scan is the previous scan, or with [Pipeline]
 * keyframe_distance / keyframe_angle the last keyframe. The matcher's guess
 * is the estimated pose of the previous scan composed with the odometry
 * increment, seen from the keyframe, with the covariance of the odometry
 * accumulated since the keyframe.
 *
 * The same loop serves every source (rawlog file, CARMEN log, live). */
class Pipeline
{
   public:
	/** `matcher` may be null when the estimator does not use one. */
	Pipeline(
		InputOptions input, OdometryOptions odometry, PipelineOptions options,
		PoseEstimator::Ptr estimator, ScanMatcher::Ptr matcher);

	/** Localization in a known map (MapLocalizer): every scan is matched
	 * against the map around the estimate and the estimator fuses it as an
	 * absolute pose (it must fusesAbsolutePoses()), or, while the pose is
	 * unknown, searched for in the whole map. Before run(). */
	void setMapLocalizer(std::shared_ptr<MapLocalizer> localizer);

	/** Processes the whole source. Every output receives every entry and
	 * step and then finish(), once, also when the run fails; the error is
	 * then rethrown. Throws InputError when the log yields no scan.
	 * `stop`: when it becomes true (SIGINT/SIGTERM) reading stops, the
	 * steps already read are processed and the run ends with
	 * RunStats::interrupted set. */
	RunStats run(
		EntrySource& source, const std::vector<RunOutput*>& outputs,
		ProgressBar* progress = nullptr, const std::atomic<bool>* stop = nullptr);

   private:
	void processStep(
		const EstimationStep& logStep, const std::vector<RunOutput*>& outputs, RunStats& stats);
	/** The matcher's motion from the keyframe scan to this step's scan. */
	MatchResult matchToKeyframe(const EstimationStep& step);

	InputOptions m_input;
	OdometryOptions m_odometry;
	PipelineOptions m_options;
	PoseEstimator::Ptr m_estimator;
	ScanMatcher::Ptr m_matcher;
	std::shared_ptr<MapLocalizer> m_mapLocalizer;
	/** The step in the map (MapLocalizer::process), counted. */
	MapLocalizer::Outcome localizeInMap(const EstimationStep& step, RunStats& stats);
	bool isNewKeyframe(const MatchResult* match) const;
	/** The step's odometry when it came from format #1 actions read off the
	 * scan's instant (EstimationStep::odometryReadOffScan), else zero. */
	static mrpt::poses::CPose2D actionStep(const EstimationStep& step);

	// The reference (keyframe) scan of the next match, the estimated pose
	// there, and the odometry since then (its covariance is the guess's).
	mrpt::obs::CObservation2DRangeScan::Ptr m_keyframeScan;
	mrpt::poses::CPose2D m_keyframePose;
	// (with the log's covariances; the guess uses them times the check's
	// factor, which scales a composed covariance exactly as its parts)
	mrpt::poses::CPosePDFGaussian m_odometrySinceKeyframe;
	/** The format #1 odometry step that ended at the keyframe scan (zero
	 * otherwise), for OdometrySamplingOffset. */
	mrpt::poses::CPose2D m_keyframeActionStep;
	/** The match before this step's failed (failed_match_keyframe_factor
	 * applies to a failure after a good match only). */
	bool m_previousMatchFailed = false;
	OdometryCovarianceCheck m_odometryCheck;
	/** Steps without odometry: the estimates' recent velocity. */
	ConstantVelocityPrior m_velocityPrior;
	mrpt::Clock::time_point m_firstStepTime;
};
}  // namespace featloc
