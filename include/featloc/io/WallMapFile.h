#pragma once
#include <Eigen/Core>

#include <string>
#include <vector>

namespace featloc
{
/** One straight wall of a known 2-D map: a vertical plane seen from above
 * (Moon, Miura & Shirai 1999: the "reference planes" of section 2.3). */
struct MapWall
{
	Eigen::Vector2d a = Eigen::Vector2d::Zero(), b = Eigen::Vector2d::Zero();  //!< ends [m]
	std::string name;  //!< "Wall.partition#0" (section and piece) or "map.txt:3"
	double length() const { return (b - a).norm(); }
};

/** A round obstacle of a world file (a pillar, a bin): not a plane, but
 * what a laser sees of it belongs in a map to localize in. */
struct MapCircle
{
	Eigen::Vector2d centre = Eigen::Vector2d::Zero();  //!< [m]
	double radius = 0;	//!< [m]
	std::string name;  //!< "Obstacle.pillar"
};

/** Reads the walls of a known 2-D map, in one of two formats:
 *  - a featloc-sim world file (doc/simulator.md): every piece of every
 *    `[Wall.<name>] polyline` (closed when `closed = true`) and every side
 *    of every `[Obstacle.<name>] polygon`; round obstacles and people are
 *    not planes and are left out;
 *  - a plain segment list: one wall per line, `x1 y1 x2 y2` [m], `#` or
 *    `%` comments.
 * A file that cannot be read, a malformed line, or a wall of zero length
 * is an InputError naming the file and the section or line. */
class WallMapFile
{
   public:
	static std::vector<MapWall> load(const std::string& path);
	/** The round obstacles (`[Obstacle.<name>] circle = [cx cy r]`) of a
	 * world file; none for a segment list. Errors as load(). */
	static std::vector<MapCircle> loadCircles(const std::string& path);
};
}  // namespace featloc
