#include "featloc/math/PoseDifference.h"

#include <mrpt/math/wrap2pi.h>

namespace featloc
{
Eigen::Vector3d poseDifference(const mrpt::poses::CPose2D& a, const mrpt::poses::CPose2D& b)
{
	return {a.x() - b.x(), a.y() - b.y(), mrpt::math::wrapToPi(a.phi() - b.phi())};
}
}  // namespace featloc
