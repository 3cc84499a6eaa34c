#include "featloc/sim/BeaconSensorOptions.h"

#include <mrpt/core/bits_math.h>

#include "featloc/config/ConfigValues.h"

namespace featloc
{
void BeaconSensorOptions::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	using namespace featloc::config;
	readRows(c, s, "points", points, {2});
	read(c, s, "label", label);
	read(c, s, "max_range", max_range);
	readDegrees(c, s, "field_of_view_DEG", field_of_view);
	read(c, s, "range_noise", range_noise);
	readDegrees(c, s, "bearing_noise_DEG", bearing_noise);
	read(c, s, "with_ids", with_ids);
	read(c, s, "occlusion", occlusion);
	std::vector<double> pose = {
		sensor_pose[0], sensor_pose[1], mrpt::RAD2DEG(sensor_pose[2])};
	read(c, s, "sensor_pose", pose);
	require(pose.size() == 3, c, s, "sensor_pose", "[x y yaw_deg]");
	sensor_pose = {pose[0], pose[1], mrpt::DEG2RAD(pose[2])};
	require(!label.empty(), c, s, "label", "a non-empty label");
	require(max_range > 0, c, s, "max_range", "> 0");
	require(
		field_of_view > 0 && field_of_view <= 2 * M_PI + 1e-9, c, s,
		"field_of_view_DEG", "in (0, 360]");
	// Zero noise would give the filter observations it must trust
	// absolutely; the sensor's covariance must be positive definite.
	require(range_noise > 0, c, s, "range_noise", "> 0");
	require(bearing_noise > 0, c, s, "bearing_noise_DEG", "> 0");
}

void BeaconSensorOptions::saveToConfigFile(
	mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	using namespace featloc::config;
	writeRows(c, s, "points", points, "[m] beacon positions [x y; ...]; none: no beacon sensor");
	write(c, s, "label", label, "sensor label of the range-bearing observations");
	write(c, s, "max_range", max_range, "[m]");
	writeDegrees(c, s, "field_of_view_DEG", field_of_view, "[deg] centred on the sensor heading");
	write(c, s, "range_noise", range_noise, "[m] Gaussian sigma");
	writeDegrees(c, s, "bearing_noise_DEG", bearing_noise, "[deg] Gaussian sigma");
	write(c, s, "with_ids", with_ids, "observations carry the beacon's index as landmark ID");
	write(c, s, "occlusion", occlusion, "walls, obstacles and people hide beacons");
	write(c, s, "sensor_pose",
		std::vector<double>{sensor_pose[0], sensor_pose[1], mrpt::RAD2DEG(sensor_pose[2])},
		"[m m deg] sensor on the robot");
}
}  // namespace featloc
