#include "featloc/math/PoseDifference.h"

#include <mrpt/math/wrap2pi.h>

#include <cmath>

namespace featloc
{
Eigen::Vector3d poseDifference(const mrpt::poses::CPose2D& a, const mrpt::poses::CPose2D& b)
{
	return {a.x() - b.x(), a.y() - b.y(), mrpt::math::wrapToPi(a.phi() - b.phi())};
}

bool posesWithin(const mrpt::poses::CPose2D& a, const mrpt::poses::CPose2D& b, double xy, double yaw)
{
	const Eigen::Vector3d d = poseDifference(a, b);
	return std::hypot(d[0], d[1]) <= xy && std::abs(d[2]) <= yaw;
}
}  // namespace featloc
