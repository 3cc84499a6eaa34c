#pragma once
#include <mrpt/math/TPoint2D.h>

#include <string>
#include <utility>
#include <vector>

#include "featloc/sim/WallSegment.h"

namespace featloc
{
/** A door turning on its hinge: to the laser one segment from the hinge
 * to its free edge, at an angle piecewise linear in the world's time
 * between keyframes (held before the first and after the last, or
 * repeated with a period). Not seen by the simulated camera. */
class SwingingDoor
{
   public:
	struct Params
	{
		std::string name;
		mrpt::math::TPoint2D hinge;	 //!< [m]
		double length = 0.9;  //!< [m] hinge to free edge
		/** (t [s], angle [rad]) keyframes, times increasing; the angle is
		 * the world direction from the hinge to the free edge. */
		std::vector<std::pair<double, double>> swing;
		/** [s] > 0: the keyframes repeat with this period (their times in
		 * [0, period)); 0: the last angle is held. */
		double period = 0;
	};

	/** Throws std::invalid_argument on no keyframe, times not increasing,
	 * a length <= 0, or a period that does not hold the keyframes. */
	explicit SwingingDoor(Params params);

	const Params& params() const { return m_params; }
	double angleAt(double t) const;
	WallSegment segmentAt(double t) const;

   private:
	Params m_params;
};
}  // namespace featloc
