#pragma once
#include <mrpt/poses/CPose2D.h>
#include <mrpt/random/RandomGenerators.h>

#include <memory>
#include <vector>

#include "featloc/sim/RobotPathOptions.h"
#include "featloc/sim/SimWorld.h"

namespace featloc
{
/** The simulated robot's true motion: a unicycle driven by a waypoint
 * follower (RobotPathOptions), integrated exactly (constant linear and
 * angular speed over each control period: circular arcs), so poseAt(t) is
 * exact at any time, for any sensor rate. */
class RobotTrajectory
{
   public:
	struct Waypoint
	{
		double x, y;
		double speed;  //!< [m/s] towards this waypoint
	};

	/** Drives from waypoints[0] through the others. Throws
	 * std::runtime_error if a waypoint is not reached in time. */
	static RobotTrajectory follow(
		const std::vector<Waypoint>& waypoints, double initialYaw,
		const RobotPathOptions& options);

	/** The trajectory [Robot] describes (waypoints or exploration).
	 * Throws std::runtime_error, naming the key, when the path driven
	 * through [Robot] waypoints or kidnap_waypoints goes through a static
	 * wall or obstacle of `world` (its scans would be taken from inside
	 * it: a log no real robot could record). */
	static RobotTrajectory fromOptions(
		const RobotPathOptions& options, const SimWorld& world,
		mrpt::random::CRandomGenerator& rng);

	mrpt::poses::CPose2D poseAt(double t) const;
	/** The motion the wheels make from t0 to t1 (t0 <= t1): the true
	 * motion, except across a kidnapping, which the wheels do not see. */
	mrpt::poses::CPose2D wheelMotion(double t0, double t1) const;
	/** [s] when the robot is carried away, or a negative number (none). */
	double kidnapTime() const { return m_kidnapped ? m_duration - m_kidnapped->m_duration : -1; }
	double duration() const { return m_duration; }
	double length() const { return m_length; }
	const std::vector<Waypoint>& waypoints() const { return m_waypoints; }

   private:
	struct Sample
	{
		mrpt::poses::CPose2D pose;	//!< at the start of the period
		double v, w;  //!< controls during the period
		size_t target;	//!< index of the waypoint driven to
	};
	/** Throws (see fromOptions) where the driven path crosses or touches a
	 * static wall or obstacle; `key` names the waypoints, `t0` is the
	 * path's start in the run. */
	void requireClearOf(const SimWorld& world, const char* key, double t0) const;
	/** The path driven after the kidnapping (from time kidnapTime()). */
	std::shared_ptr<const RobotTrajectory> m_kidnapped;
	mrpt::poses::CPose2D ownPoseAt(double t) const;
	std::vector<Sample> m_samples;
	std::vector<Waypoint> m_waypoints;
	double m_period = 0.01;
	double m_duration = 0;
	double m_length = 0;
};
}  // namespace featloc
