#pragma once
#include <mrpt/config/CLoadableOptions.h>
#include <mrpt/core/bits_math.h>

#include <string>
#include <vector>

namespace featloc
{
/** `[Robot]` of a world file: how the simulated robot moves.
 *
 * A differential-drive (unicycle) robot drives towards each waypoint in
 * turn: it turns in place while the heading error exceeds turn_in_place,
 * otherwise drives at `speed` while steering (angular speed limited to
 * max_angular_speed). With path = explore, the waypoints are random goals in
 * the free space whose straight connections keep explore_clearance from
 * every wall and obstacle (drawn from the simulation seed). */
struct RobotPathOptions : public mrpt::config::CLoadableOptions
{
	static constexpr const char* kSection = "Robot";

	std::string path = "waypoints";	 //!< waypoints | explore
	/** Rows [x y] or [x y speed]; the first is the start. */
	std::vector<std::vector<double>> waypoints = {{0, 0}, {2, 0}};
	/** "auto" (face the second waypoint) or degrees. */
	std::string initial_yaw = "auto";
	double speed = 0.5;	 //!< [m/s]
	double max_angular_speed = mrpt::DEG2RAD(60.0);	//!< [rad/s]
	double turn_in_place = mrpt::DEG2RAD(20.0);	 //!< [rad]
	double goal_tolerance = 0.1;  //!< [m]
	unsigned int laps = 1;	//!< drive the waypoint list this many times
	unsigned int explore_goals = 20;
	double explore_clearance = 0.5;	 //!< [m]
	std::vector<double> explore_start = {0, 0};	//!< [m m]
	double control_period = 0.01;  //!< [s] integration step
	/** The kidnapped robot: rows [x y] or [x y speed] (empty: none). When
	 * the path above ends, the robot is carried to the first of these and
	 * drives through the others; its odometry does not see the carrying
	 * (wheels still: no motion), the ground truth does. */
	std::vector<std::vector<double>> kidnap_waypoints;

	void loadFromConfigFile(
		const mrpt::config::CConfigFileBase& c,
		const std::string& s) override;
	void saveToConfigFile(
		mrpt::config::CConfigFileBase& c, const std::string& s) const override;
};
}  // namespace featloc
