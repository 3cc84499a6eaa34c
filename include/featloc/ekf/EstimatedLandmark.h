#pragma once
#include <Eigen/Core>
#include <cstdint>

namespace featloc
{
/** A point landmark in the filter's map, with its marginal covariance. */
struct EstimatedLandmark
{
	int64_t id = -1;  //!< the sensor's identity, or -1
	Eigen::Vector2d mean = Eigen::Vector2d::Zero();	 //!< world frame [m]
	Eigen::Matrix2d covariance = Eigen::Matrix2d::Zero();
	unsigned int observations = 0;	//!< times it was observed (its first included)
};
}  // namespace featloc
