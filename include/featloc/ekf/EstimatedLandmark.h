#pragma once
#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <string>

namespace featloc
{
/** A landmark in the filter's map, with its marginal covariance: a point
 * (x, y), or a vertical line (Moon, Miura & Shirai): its foot (x, y) on a
 * map wall and the heights of its ends. */
struct EstimatedLandmark
{
	int64_t id = -1;  //!< the sensor's identity, or -1
	Eigen::Vector2d mean = Eigen::Vector2d::Zero();	 //!< world frame [m]
	Eigen::Matrix2d covariance = Eigen::Matrix2d::Zero();
	unsigned int observations = 0;	//!< times it was observed (its first included)
	bool vertical = false;
	size_t wall = 0;  //!< vertical: the map wall it lies on
	std::string plane;	//!< its name (filled by the estimator)
	double lLow = 0, lHigh = 0;	 //!< vertical: heights of its ends [m]
	double sigmaLow = 0, sigmaHigh = 0;	 //!< [m]
};
}  // namespace featloc
