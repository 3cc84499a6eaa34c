#pragma once
#include <mrpt/math/TPoint2D.h>

#include <string>
#include <vector>

#include "featloc/sim/SurfacePatch.h"

namespace featloc
{
/** One straight piece of a wall or obstacle outline, in world coordinates,
 * with what the simulated camera sees on it: `texture` (a SurfaceMaterial
 * name) from `bottom` to `top` above the floor, and patches of other
 * materials. `object` is the world-file section it came from. The laser
 * sees only a, b. */
struct WallSegment
{
	mrpt::math::TPoint2D a, b;	//!< end points [m]
	std::string texture = "plain";
	std::string object;
	double bottom = 0, top = 2.5;  //!< [m] vertical extent
	/** [m] distance along the object's polyline from its first point to
	 * a (texture and patch coordinates run along the whole polyline). */
	double sStart = 0;
	/** Patches of the whole object (s in polyline coordinates). */
	std::vector<SurfacePatch> patches;
	/** Outline of a solid obstacle (a camera above it sees its top), not a
	 * wall one can stand on either side of. */
	bool solid = false;
};
}  // namespace featloc
