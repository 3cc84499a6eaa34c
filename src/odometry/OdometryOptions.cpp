#include "featloc/odometry/OdometryOptions.h"

#include "featloc/config/ConfigValues.h"

namespace featloc
{
void OdometryOptions::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	using namespace featloc::config;
	readChoice(c, s, "covariance_source", covariance_source, {"rawlog", "model"});
	model.loadFromConfigFile(c, s);
	read(c, s, "max_interpolation_gap", max_interpolation_gap);
	read(c, s, "no_odometry_sigma_xy", no_odometry_sigma_xy);
	readDegrees(c, s, "no_odometry_sigma_yaw_DEG", no_odometry_sigma_yaw);
	require(max_interpolation_gap > 0, c, s, "max_interpolation_gap", "> 0");
	require(no_odometry_sigma_xy > 0, c, s, "no_odometry_sigma_xy", "> 0");
	require(
		no_odometry_sigma_yaw > 0, c, s, "no_odometry_sigma_yaw_DEG", "> 0");
}

void OdometryOptions::saveToConfigFile(
	mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	using namespace featloc::config;
	write(c, s, "covariance_source", covariance_source,
		"rawlog | model: covariance of format #1 actions");
	model.saveToConfigFile(c, s);
	write(c, s, "max_interpolation_gap", max_interpolation_gap,
		"[s] format #2: max gap between odometry readings to interpolate");
	write(c, s, "no_odometry_sigma_xy", no_odometry_sigma_xy,
		"[m] prior sigma of a step without odometry (zero motion)");
	writeDegrees(c, s, "no_odometry_sigma_yaw_DEG", no_odometry_sigma_yaw,
		"[deg] prior yaw sigma of a step without odometry");
}
}  // namespace featloc
