#pragma once
#include <mrpt/math/TPose2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <optional>
#include <string>
#include <vector>

namespace featloc
{
struct InputOptions;

/** One FLASER message of a CARMEN log. */
struct CarmenScan
{
	double time = 0;  //!< logger_timestamp [s]
	mrpt::obs::CObservation2DRangeScan::Ptr scan;
	mrpt::math::TPose2D pose;  //!< x y theta (corrected logs: the reference)
	mrpt::math::TPose2D odometry;  //!< odom_x odom_y odom_theta
	/** The robot's odometry at this scan from the ODOM messages, chained
	 * across re-anchoring lines (see CarmenLogReader): a pose in a frame
	 * of its own, whose increments are the wheel odometry's. Empty when no
	 * ODOM message (other than a re-anchoring one) came since the previous
	 * scan, and on the first scan when no ODOM message came before it. */
	std::optional<mrpt::math::TPose2D> odomMessages;
	size_t line = 0;  //!< 1-based line in the file
};

/** Reads the FLASER messages of a CARMEN log (plain or gzip):
 *   FLASER n r_1 .. r_n x y theta odom_x odom_y odom_theta ipc_time host logger_time
 * n ranges over 180 degrees, right to left, in metres; the scan is stamped
 * with logger_time (MRPT 2.5.8's carmen2rawlog stamps every observation
 * alike). The laser's offset on the robot comes from
 * "PARAM robot_frontlaser_offset" (along x).
 *
 * "No return" is written as the sensor's maximum, which differs between
 * logs (81.91, 51.15, 32.767 m...): readings at or beyond `maxRange` are
 * marked invalid. A malformed line is an InputError naming file and line.
 *
 * ODOM messages (`ODOM x y theta tv rv accel ...`) are the wheel odometry
 * stream. A corrected log (the Radish "-corrected" logs, written by a
 * GMapping/GFS run) overwrites every FLASER's odom fields with the
 * corrected pose, and after each FLASER writes an ODOM message at that
 * corrected pose (timestamps 0): the stream is re-anchored at every scan
 * and the ODOM messages that follow move on from there by the wheels'
 * increments. Such an ODOM message (the first after a FLASER, at exactly
 * its x y theta) is recognised as an anchor: it restarts the chain without
 * adding motion, so odomMessages keeps the raw odometry's increments
 * between scans. */
class CarmenLogReader
{
   public:
	struct Options
	{
		double maxRange = 30.0;	 //!< [m]
		std::string label = "FLASER";
		/** Where a FLASER message's n beams point (the format does not say):
		 * "sick" (default): the first at -90 deg (right), one step apart,
		 * the step being whichever of 180/n and 180/(n-1) deg is a SICK
		 * scanner's resolution (1, 0.5 or 0.25 deg): 180 and 360 beams are
		 * 1 and 0.5 deg apart and end one step short of +90 deg (CARMEN's
		 * and GMapping's reading, which the Radish logs' corrected poses
		 * agree with); 181 and 361 beams span -90 to +90 deg; other counts
		 * as "even". "even": n beams evenly over -90 to +90 deg (MRPT's
		 * carmen2rawlog). */
		std::string beamAngles = "sick";

		/** The options [Input] gives (carmen_beam_angles). */
		static Options from(const InputOptions& input);
	};
	/** The step [rad] between a FLASER message's n beams and the bearing
	 * [rad] of its first (right-most) beam, as options.beamAngles says. */
	static void beamAngles(size_t n, const std::string& convention, double& step, double& first);
	static std::vector<CarmenScan> read(const std::string& path, const Options& options);
};
}  // namespace featloc
