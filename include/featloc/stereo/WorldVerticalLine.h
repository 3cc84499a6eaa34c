#pragma once
#include <Eigen/Core>

#include <cstddef>

namespace featloc
{
/** A vertical line seen by one stereo pair at a known camera pose, in the
 * world frame (z up): where it crosses the floor plan, with that point's
 * covariance, and the heights of its ends [m]. */
struct WorldVerticalLine
{
	Eigen::Vector2d xy = Eigen::Vector2d::Zero();
	Eigen::Matrix2d cov = Eigen::Matrix2d::Zero();
	double zLow = 0, zHigh = 0;
	int polarity = 0;  //!< the left segment's (VerticalSegment::polarity)
	double tiltDeg = 0;	 //!< its 3-D direction's angle from the world's z axis
	double depth = 0;  //!< [m] from the left camera, along its optical axis
	size_t match = 0;  //!< index into StereoVerticalLines::Result::matches
};
}  // namespace featloc
