#pragma once
#include <mrpt/math/CMatrixFixed.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>

#include "featloc/sim/SimWorld.h"

namespace featloc
{
/** The Fisher information that a simulated 2-D range scan carries about the
 * robot pose that took it, against the world's true surfaces (Censi, "On
 * achievable accuracy for range-finder localization", ICRA 2007):
 *
 *   I = sum_i g_i g_i^T / sigma^2,   g_i = d r_i / d (x, y, theta),
 *
 * where, for beam i of world direction v (angle theta + mount yaw + its
 * bearing) from the sensor s = t + R(theta) l hitting a surface of unit
 * normal n at range r (a circle counts as its tangent there: curvature is
 * of second order),
 *
 *   d r / d t     = -n^T / (n . v),
 *   d r / d theta = -(n . R'(theta) l + r n . v') / (n . v),  v' = dv/dtheta.
 *
 * sigma is the scan's own stdError (the simulator's range noise). A beam
 * counts when the scan has it valid and, cast exactly from the true pose,
 * it hits a static wall or obstacle: beams on a walking person, a cart or
 * a door (where they are at the scan's time) or on nothing carry no
 * information about the pose. */
class RangeScanFisherInformation
{
   public:
	struct Result
	{
		mrpt::math::CMatrixDouble33 information;  //!< of (x, y, yaw) of the robot
		size_t beamsUsed = 0;  //!< the beams that counted
		/** Valid beams whose measured range is more than 5 sigma from the
		 * exact one (or that hit nothing): many of them say that the scan
		 * was not taken in this world at this pose. */
		size_t beamsOff = 0;
		size_t beamsValid = 0;
	};
	/** `robot`: the true robot pose; `t`: the world's time of the scan [s]
	 * (scan time minus [Simulation] t0, where the people are). Throws
	 * std::invalid_argument when the scan declares no range noise
	 * (stdError <= 0). */
	static Result of(const SimWorld& world, double t,
		const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::poses::CPose2D& robot);
};
}  // namespace featloc
