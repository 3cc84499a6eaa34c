#include "featloc/sim/RobotPathOptions.h"

#include <cstdlib>

#include "featloc/config/ConfigValues.h"

namespace featloc
{
void RobotPathOptions::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	using namespace featloc::config;
	readChoice(c, s, "path", path, {"waypoints", "explore"});
	readRows(c, s, "waypoints", waypoints, {2, 3});
	readRows(c, s, "kidnap_waypoints", kidnap_waypoints, {2, 3});
	require(kidnap_waypoints.empty() || kidnap_waypoints.size() >= 2, c, s, "kidnap_waypoints",
		"empty, or at least two points [x y; x y]");
	for (const auto& w : kidnap_waypoints)
		require(w.size() == 2 || w[2] > 0, c, s, "kidnap_waypoints", "speeds (third column) > 0");
	read(c, s, "initial_yaw_DEG", initial_yaw);
	if (initial_yaw != "auto")
	{
		double deg = 0;
		readDegrees(c, s, "initial_yaw_DEG", deg);	// validates the number
	}
	read(c, s, "speed", speed);
	readDegrees(c, s, "max_angular_speed_DEG", max_angular_speed);
	readDegrees(c, s, "turn_in_place_DEG", turn_in_place);
	read(c, s, "goal_tolerance", goal_tolerance);
	read(c, s, "laps", laps);
	read(c, s, "explore_goals", explore_goals);
	read(c, s, "explore_clearance", explore_clearance);
	read(c, s, "explore_start", explore_start);
	read(c, s, "control_period", control_period);

	require(path == "explore" || waypoints.size() >= 2, c, s, "waypoints",
		"at least two rows [x y] or [x y speed]");
	for (const auto& w : waypoints)
		require(w.size() == 2 || w[2] > 0, c, s, "waypoints",
			"made of rows whose speed (third number) is > 0");
	require(speed > 0, c, s, "speed", "> 0");
	require(max_angular_speed > 0, c, s, "max_angular_speed_DEG", "> 0");
	require(turn_in_place > 0 && turn_in_place < M_PI / 2, c, s,
		"turn_in_place_DEG", "in (0, 90)");
	require(goal_tolerance > 0, c, s, "goal_tolerance", "> 0");
	require(laps >= 1, c, s, "laps", ">= 1");
	require(explore_goals >= 1, c, s, "explore_goals", ">= 1");
	require(explore_clearance > 0, c, s, "explore_clearance", "> 0");
	require(explore_start.size() == 2, c, s, "explore_start", "[x y]");
	require(control_period > 0 && control_period <= 0.1, c, s,
		"control_period", "in (0, 0.1]");
}

void RobotPathOptions::saveToConfigFile(
	mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	using namespace featloc::config;
	write(c, s, "path", path, "waypoints | explore (random goals in free space)");
	writeRows(c, s, "waypoints", waypoints,
		"[x y; ...] or [x y speed; ...] in m, m/s; the first is the start");
	writeRows(c, s, "kidnap_waypoints", kidnap_waypoints,
		"the kidnapped robot: after the path, carried (odometry blind) to the first of these "
		"and driven through the others; empty: none");
	write(c, s, "initial_yaw_DEG", initial_yaw,
		"auto (face the second waypoint) or degrees");
	write(c, s, "speed", speed, "[m/s] cruise speed");
	writeDegrees(c, s, "max_angular_speed_DEG", max_angular_speed, "[deg/s]");
	writeDegrees(c, s, "turn_in_place_DEG", turn_in_place,
		"[deg] turn on the spot while the heading error is larger");
	write(c, s, "goal_tolerance", goal_tolerance, "[m] a waypoint is reached within this");
	write(c, s, "laps", laps, "drive the waypoint list this many times");
	write(c, s, "explore_goals", explore_goals, "explore: number of random goals");
	write(c, s, "explore_clearance", explore_clearance,
		"[m] explore: min distance of the path to walls and obstacles");
	write(c, s, "explore_start", explore_start, "[m m] explore: start position");
	write(c, s, "control_period", control_period,
		"[s] control and integration step of the robot motion");
}
}  // namespace featloc
