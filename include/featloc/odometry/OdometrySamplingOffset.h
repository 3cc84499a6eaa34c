#pragma once
#include <mrpt/math/CMatrixFixed.h>
#include <mrpt/poses/CPose2D.h>

namespace featloc
{
/** The error of the odometry at a scan when the odometry was not read at
 * the scan's instant: in format #1 rawlogs the odometry increment paired
 * with a scan is whatever the robot reported between two scans, and the
 * reading may lead or lag the scan by a fraction of the interval. Over a
 * step of increment D, an offset of a fraction f of the interval, f uniform
 * in [-1/2, 1/2], misplaces the pose by f D (variance D D^T / 12, rank 1,
 * along the step), at the keyframe scan and at the current scan alike.
 * Unlike the Gaussian model's per-metre noise it does not accumulate: the
 * next reading puts the odometry back where it should be.
 *
 * On MRPT's simulated log (the bundled default) the odometry's largest
 * errors are of this kind: after the log's irregular steps one step falls
 * short by up to 0.46 m and the next overshoots by as much
 * (scripts/odometry-step-errors.py; doc/benchmarks.md, "Odometry read off
 * the scan's instant"). */
class OdometrySamplingOffset
{
   public:
	/** Covariance (x, y, yaw) of the error of one reading, at the end of
	 * the step `step` (f D, f uniform in [-1/2, 1/2]). */
	static mrpt::math::CMatrixDouble33 ofReading(const mrpt::poses::CPose2D& step);
	/** Covariance (x, y, yaw) of the motion keyframe -> current from the
	 * two ends: `keyframeStep`, the increment that ended at the keyframe
	 * scan (in the keyframe's frame, near enough), and `currentStep`, the
	 * one that ended at the current scan, rotated by the motion's yaw into
	 * the keyframe's frame. */
	static mrpt::math::CMatrixDouble33 covariance(
		const mrpt::poses::CPose2D& keyframeStep, const mrpt::poses::CPose2D& currentStep,
		const mrpt::poses::CPose2D& motion);
};
}  // namespace featloc
