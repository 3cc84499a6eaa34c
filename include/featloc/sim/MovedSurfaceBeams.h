#pragma once
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>

#include <cstdint>
#include <vector>

#include "featloc/sim/SimWorld.h"

namespace featloc
{
/** Which points of a simulated scan lie on something that moved since an
 * earlier time: the beams (scan indices, ascending) whose exact hit point,
 * cast from the true pose at the scan's time, is farther than `tolerance`
 * from every surface of the world as it was at `earlier` (walls, obstacles,
 * and people, carts and doors where they were then). A matcher that pairs
 * such a point with the earlier scan pairs it with nothing that is there:
 * these are what CF-IDC's stages should drop. A person who stood still, a
 * door held open, count as not moved. */
class MovedSurfaceBeams
{
   public:
	static std::vector<uint32_t> of(const SimWorld& world, double t,
		const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::poses::CPose2D& robot,
		double earlier, double tolerance = 0.02);
};
}  // namespace featloc
