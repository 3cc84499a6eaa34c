#pragma once
#include <mrpt/math/TPose2D.h>

#include <vector>

#include "featloc/sim/CircleShape.h"
#include "featloc/sim/WallSegment.h"

namespace featloc
{
/** Exact 2-D ray casting of a fan of beams against segments and circles.
 *
 * Each beam is the half-line from the sensor at angle
 * sensor.phi + firstAngle + i * step; its range is the distance to the
 * nearest intersection (exact line-segment and line-circle solutions in
 * double precision), or +infinity when nothing is hit within maxRange.
 *
 * Speed: instead of testing every beam against every shape, each shape is
 * tested only against the beams inside the angular interval it subtends
 * from the sensor (per-beam culling), so the cost grows with the number of
 * beams times the depth complexity, not beams x shapes. Circles containing
 * the sensor are ignored. */
class RayCaster
{
   public:
	/** What a beam hit (when its range is finite). */
	struct Hit
	{
		bool circle = false;  //!< circles[index], else segments[index]
		size_t index = 0;
		double normal = 0;	//!< [rad] world angle of the surface's normal there
	};

	/** With `hits`: also what each beam hit (the entries of infinite
	 * ranges mean nothing). */
	static void cast(
		const mrpt::math::TPose2D& sensor, double firstAngle, double step,
		size_t beams, double maxRange, const std::vector<WallSegment>& segments,
		const std::vector<CircleShape>& circles, std::vector<double>& ranges,
		std::vector<Hit>* hits = nullptr);
};
}  // namespace featloc
