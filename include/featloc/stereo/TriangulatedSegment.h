#pragma once
#include <Eigen/Core>

namespace featloc
{
/** A matched pair of vertical segments as a 3-D segment in the rectified
 * left camera's frame (x right, y down, z ahead) [m]: its top and bottom
 * ends (the match's common rows) and its middle, each with the covariance
 * of its position. */
struct TriangulatedSegment
{
	Eigen::Vector3d top = Eigen::Vector3d::Zero(), bottom = Eigen::Vector3d::Zero(),
					middle = Eigen::Vector3d::Zero();
	Eigen::Matrix3d covTop = Eigen::Matrix3d::Zero(), covBottom = Eigen::Matrix3d::Zero(),
					covMiddle = Eigen::Matrix3d::Zero();
};
}  // namespace featloc
