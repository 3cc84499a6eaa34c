#pragma once
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/obs_frwds.h>
#include <mrpt/poses/CPosePDFGaussian.h>

#include <cstddef>
#include <memory>
#include <vector>

#include "featloc/ekf/LandmarkObservation.h"

namespace featloc
{
struct DecodedStereoPair;

/** One observation frame to process: what the sensors saw at one time (a
 * 2-D scan, point landmarks, a stereo pair, or several), with the robot motion since the
 * previous step as measured by odometry. Steps come in time order; every
 * step gives one row of every output.
 *
 * A frame is a rawlog sensory frame of a format #1 log (its observations
 * were taken at one robot pose, the action before it is the motion), or the
 * observations that share one timestamp (format #2, or frames without
 * actions, where odometry is interpolated at each frame's own time). */
struct EstimationStep
{
	size_t index = 0;  //!< 0-based among the steps of the run
	/** 0-based among the steps that hold a scan (valid when scan). */
	size_t scanIndex = 0;
	size_t entryIndex = 0;	//!< rawlog entry holding the primary observation
	mrpt::Clock::time_point time{};
	/** The scan to use (a cleaned copy when beams were invalidated), or
	 * null when the frame has no selected scan. */
	mrpt::obs::CObservation2DRangeScan::Ptr scan;
	/** The observation the outputs attach the estimated pose to (the scan
	 * if there is one, else the frame's first used observation). */
	const mrpt::obs::CObservation* source = nullptr;
	/** False for the first step, and when no odometry covers this step:
	 * then `odometry` is zero motion with the [Odometry] no_odometry_*
	 * sigmas (identity with zero covariance for the first step); the
	 * Pipeline replaces that motion by the estimate's recent velocity
	 * (no_odometry_prior = constant_velocity). */
	bool hasOdometry = false;
	/** Robot motion from the previous step to this one (robot frame of the
	 * previous step), with covariance. */
	mrpt::poses::CPosePDFGaussian odometry;
	/** `odometry` is the sum of format #1 actions: what the robot reported
	 * between two scans, read at an instant the log does not give (it may
	 * lead or lag the scan: OdometrySamplingOffset). False when it was
	 * interpolated at the scan's own time (format #2, CARMEN logs). */
	bool odometryFromActions = false;
	/** With odometryFromActions: the last action is stamped with this
	 * step's time (to a millisecond), so it was read at the scan's instant
	 * and has no sampling offset (featloc-sim's logs; MRPT's simulated log
	 * leaves its actions unstamped, Malaga's are stamped 0.1 s before their
	 * scans). */
	bool odometryReadAtScan = false;
	/** Format #1 odometry read at an instant the log does not give (or
	 * not at the scan's): what [Odometry] action_sampling_offset models. */
	bool odometryReadOffScan() const { return odometryFromActions && !odometryReadAtScan; }
	/** Covariance of the error of this step's odometry reading at this
	 * scan (robot frame at this scan) when it was read off the scan's
	 * instant: D D^T / 12 for the step's increment D
	 * (OdometrySamplingOffset; [Odometry] action_sampling_offset). Zero
	 * otherwise. The EKF keeps the error in its state. */
	mrpt::math::CMatrixDouble33 odometrySamplingCovariance;
	/** Point landmarks observed in this frame (robot frame). */
	std::vector<LandmarkObservation> landmarks;
	/** A stereo pair of this frame (checked: calibration, images that
	 * exist and decode), or null. */
	std::shared_ptr<mrpt::obs::CObservationStereoImages> stereo;
	/** Its images, decoded grey (with `stereo`). */
	std::shared_ptr<const DecodedStereoPair> stereoImages;
};
}  // namespace featloc
