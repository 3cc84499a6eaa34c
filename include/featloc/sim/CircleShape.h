#pragma once
#include <mrpt/math/TPoint2D.h>

#include <string>

namespace featloc
{
/** A circular obstacle (pillar, bin) or a moving body part (a leg, a
 * torso), in world coordinates; to the camera a vertical cylinder from
 * `bottom` to `top`. */
struct CircleShape
{
	mrpt::math::TPoint2D centre;  //!< [m]
	double radius = 0;	//!< [m]
	std::string texture = "plain";
	std::string object;
	double bottom = 0, top = 1.0;  //!< [m] vertical extent
};
}  // namespace featloc
