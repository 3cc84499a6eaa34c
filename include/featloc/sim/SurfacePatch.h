#pragma once
#include <string>

namespace featloc
{
/** A rectangle of another material on a wall (a poster, a door, a sheet
 * of paper pinned on a partition): its vertical sides are vertical edges a
 * camera sees. Coordinates on the wall: s [m] along the wall's polyline
 * from its first point, z [m] above the floor. */
struct SurfacePatch
{
	double s0 = 0, s1 = 0;	//!< [m] s0 < s1
	double z0 = 0, z1 = 0;	//!< [m] z0 < z1
	std::string texture;
};
}  // namespace featloc
