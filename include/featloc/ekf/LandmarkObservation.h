#pragma once
#include <mrpt/obs/obs_frwds.h>

#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace featloc
{
/** One observed point landmark: its position in the robot frame with its
 * own 2x2 covariance (every observation may have a different one: a stereo
 * landmark far away is much less certain than one nearby), and its identity
 * when the sensor knows it. */
struct LandmarkObservation
{
	Eigen::Vector2d position = Eigen::Vector2d::Zero();	 //!< robot frame [m]
	Eigen::Matrix2d covariance = Eigen::Matrix2d::Identity();  //!< [m^2]
	int64_t id = -1;  //!< -1: unknown, the filter associates it

	/** The observations of an MRPT range-bearing observation (2-D: pitch
	 * ignored), moved from the sensor to the robot frame, each covariance
	 * propagated from range and bearing (its own 3x3 covariance when the
	 * observation has them, else sensor_std_range / sensor_std_yaw). */
	static std::vector<LandmarkObservation> fromBearingRange(
		const mrpt::obs::CObservationBearingRange& obs);
};
}  // namespace featloc
