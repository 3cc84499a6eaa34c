#pragma once
#include <mrpt/poses/CPose2D.h>

#include <Eigen/Core>

namespace featloc
{
/** a - b as the vector (x, y, yaw) with the yaw difference wrapped to
 * (-pi, pi]: the error or innovation of pose a against pose b, both in one
 * frame (what Mahalanobis distances and NEES are computed on). */
Eigen::Vector3d poseDifference(const mrpt::poses::CPose2D& a, const mrpt::poses::CPose2D& b);

/** Whether a and b are at most `xy` [m] apart and turned at most `yaw`
 * [rad] from each other: one solution, one hypothesis (not distinct). */
bool posesWithin(const mrpt::poses::CPose2D& a, const mrpt::poses::CPose2D& b, double xy, double yaw);
}  // namespace featloc
