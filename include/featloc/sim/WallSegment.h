#pragma once
#include <mrpt/math/TPoint2D.h>

#include <string>

namespace featloc
{
/** One straight piece of a wall or obstacle outline, in world coordinates.
 * `texture` names the pattern a camera would see on it (stereo simulation
 * comes later); `object` is the world-file section it came from. */
struct WallSegment
{
	mrpt::math::TPoint2D a, b;	//!< end points [m]
	std::string texture = "plain";
	std::string object;
};
}  // namespace featloc
