#pragma once
#include <mrpt/math/TPose2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <string>
#include <vector>

namespace featloc
{
/** One FLASER message of a CARMEN log. */
struct CarmenScan
{
	double time = 0;  //!< logger_timestamp [s]
	mrpt::obs::CObservation2DRangeScan::Ptr scan;
	mrpt::math::TPose2D pose;  //!< x y theta (corrected logs: the reference)
	mrpt::math::TPose2D odometry;  //!< odom_x odom_y odom_theta
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
 * marked invalid. A malformed line is an InputError naming file and line. */
class CarmenLogReader
{
   public:
	struct Options
	{
		double maxRange = 30.0;	 //!< [m]
		std::string label = "FLASER";
	};
	static std::vector<CarmenScan> read(const std::string& path, const Options& options);
};
}  // namespace featloc
