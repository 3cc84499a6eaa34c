#pragma once
#include <mrpt/poses/CPose2D.h>
#include <mrpt/random/RandomGenerators.h>

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

	/** The trajectory [Robot] describes (waypoints or exploration). */
	static RobotTrajectory fromOptions(
		const RobotPathOptions& options, const SimWorld& world,
		mrpt::random::CRandomGenerator& rng);

	mrpt::poses::CPose2D poseAt(double t) const;
	double duration() const { return m_duration; }
	double length() const { return m_length; }
	const std::vector<Waypoint>& waypoints() const { return m_waypoints; }

   private:
	struct Sample
	{
		mrpt::poses::CPose2D pose;	//!< at the start of the period
		double v, w;  //!< controls during the period
	};
	std::vector<Sample> m_samples;
	std::vector<Waypoint> m_waypoints;
	double m_period = 0.01;
	double m_duration = 0;
	double m_length = 0;
};
}  // namespace featloc
