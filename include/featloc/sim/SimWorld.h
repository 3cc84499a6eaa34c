#pragma once
#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/math/TPoint2D.h>

#include <vector>

#include "featloc/sim/CircleShape.h"
#include "featloc/sim/RayCaster.h"
#include "featloc/sim/SwingingDoor.h"
#include "featloc/sim/WalkingAgent.h"
#include "featloc/sim/WallSegment.h"

namespace mrpt::obs
{
class CObservation2DRangeScan;
}
namespace mrpt::poses
{
class CPose2D;
}

namespace featloc
{
/** The simulated world: static walls and obstacles (segments and circles,
 * each with a texture name), and what moves: people walking through it,
 * carts pushed through it and doors that swing.
 *
 * World file sections (ini, or YAML with the same names, see
 * doc/simulator.md):
 *   [Wall.<name>]     polyline = [x y; x y; ...], closed = false, texture,
 *                     bottom, height, posters, patches, patch_texture, doors
 *   [Obstacle.<name>] polygon = [x y; ...] or circle = [cx cy r], texture,
 *                     height
 *   [Agent.<name>]    shape = legs|body|cart, waypoints = [...], speed, pause,
 *                     mode = loop|pingpong|once, start_time, sizes
 *   [Door.<name>]     hinge = [x y], length, swing = [t deg; ...] */
class SimWorld
{
   public:
	static SimWorld fromConfig(const mrpt::config::CConfigFileBase& cfg);

	void addSegment(const WallSegment& s) { m_segments.push_back(s); }
	void addCircle(const CircleShape& c) { m_circles.push_back(c); }
	void addAgent(const WalkingAgent::Params& p) { m_agents.emplace_back(p); }
	void addDoor(const SwingingDoor::Params& p) { m_doors.emplace_back(p); }

	const std::vector<WallSegment>& segments() const { return m_segments; }
	const std::vector<CircleShape>& circles() const { return m_circles; }
	const std::vector<WalkingAgent>& agents() const { return m_agents; }
	const std::vector<SwingingDoor>& doors() const { return m_doors; }

	/** The same world with nothing moving: no agents, and every door held
	 * at its angle at t = 0 (featloc-sim --frozen). A matcher's error on a
	 * log of this world, against its error on the world's own log along
	 * the same path, is what the moving things cost it: the floor that
	 * rejecting them can reach. */
	SimWorld frozen() const;

	/** The segments the laser sees at time t: the static ones (first, in
	 * the order of segments()), then every door's and every cart's. Without
	 * doors and carts that is segments() itself (no copy); otherwise they
	 * are put in `scratch`, which is returned. */
	const std::vector<WallSegment>& segmentsAt(double t, std::vector<WallSegment>& scratch) const;
	/** Static circles plus every agent's circles at time t. */
	void circlesAt(double t, std::vector<CircleShape>& out) const;
	/** The same as the camera sees them: people with torso and head. */
	void cameraCirclesAt(double t, std::vector<CircleShape>& out) const;

	/** Distance from p to the nearest static wall or obstacle [m]. */
	double clearance(const mrpt::math::TPoint2D& p) const;
	/** Distance from each point to the nearest surface at time t [m]:
	 * walls, obstacles, and people, carts and doors where they are then (a
	 * circle counts by its outline, inside or out). */
	std::vector<double> distancesToSurfaces(
		const std::vector<mrpt::math::TPoint2D>& points, double t) const;

	/** The exact ranges of a 2-D scan's beams from `sensor` at time t, in
	 * the simulator's beam order (from -aperture / 2, turning left:
	 * index k is the scan's k if it is right-to-left, else n - 1 - k), and
	 * with `hits` what each hit (RayCaster::Hit: an index into
	 * segmentsAt(t) or circlesAt(t), whose static shapes come first). */
	void castScan(double t, const mrpt::poses::CPose2D& sensor,
		const mrpt::obs::CObservation2DRangeScan& scan, std::vector<double>& ranges,
		std::vector<RayCaster::Hit>* hits = nullptr) const;
	/** True when the straight path a-b stays at least `clearance` away from
	 * every static wall and obstacle. */
	bool pathIsClear(
		const mrpt::math::TPoint2D& a, const mrpt::math::TPoint2D& b,
		double clearance) const;
	/** Bounding box of the static geometry: min and max corners. */
	std::pair<mrpt::math::TPoint2D, mrpt::math::TPoint2D> bounds() const;

   private:
	std::vector<WallSegment> m_segments;
	std::vector<CircleShape> m_circles;
	std::vector<WalkingAgent> m_agents;
	std::vector<SwingingDoor> m_doors;
};
}  // namespace featloc
