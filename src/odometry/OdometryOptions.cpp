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
	read(c, s, "max_extrapolation", max_extrapolation);
	readChoice(c, s, "no_odometry_prior", no_odometry_prior, {"constant_velocity", "zero"});
	read(c, s, "no_odometry_velocity_window", no_odometry_velocity_window);
	require(no_odometry_velocity_window > 0, c, s, "no_odometry_velocity_window", "> 0");
	read(c, s, "no_odometry_sigma_xy", no_odometry_sigma_xy);
	readDegrees(c, s, "no_odometry_sigma_yaw_DEG", no_odometry_sigma_yaw);
	read(c, s, "action_sampling_offset", action_sampling_offset);
	read(c, s, "covariance_check", covariance_check);
	read(c, s, "covariance_check_window", covariance_check_window);
	read(c, s, "covariance_check_quantile", covariance_check_quantile);
	require(covariance_check_quantile >= 0.5 && covariance_check_quantile <= 0.99, c, s,
		"covariance_check_quantile", "in [0.5, 0.99]");
	require(max_interpolation_gap > 0, c, s, "max_interpolation_gap", "> 0");
	require(max_extrapolation >= 0 && max_extrapolation <= max_interpolation_gap, c, s,
		"max_extrapolation", "in [0, max_interpolation_gap]");
	require(covariance_check_window >= 3, c, s, "covariance_check_window", ">= 3");
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
	write(c, s, "max_extrapolation", max_extrapolation,
		"[s] format #2: a scan this close after the newest reading extrapolates it rather than wait for the next (live runs; 0: always wait)");
	write(c, s, "no_odometry_prior", no_odometry_prior,
		"constant_velocity | zero: motion of a step without odometry (the estimate's recent velocity, or none)");
	write(c, s, "no_odometry_velocity_window", no_odometry_velocity_window,
		"[s] constant_velocity: the velocity is the estimate's over this long");
	write(c, s, "no_odometry_sigma_xy", no_odometry_sigma_xy,
		"[m] prior sigma of a step without odometry");
	writeDegrees(c, s, "no_odometry_sigma_yaw_DEG", no_odometry_sigma_yaw,
		"[deg] prior yaw sigma of a step without odometry");
	write(c, s, "action_sampling_offset", action_sampling_offset,
		"the matchers' guess gates and the EKF (in its state) allow for format #1 odometry read off the scan's instant");
	write(c, s, "covariance_check", covariance_check,
		"inflate the odometry covariance when the matches show it is too small");
	write(c, s, "covariance_check_window", covariance_check_window,
		"covariance_check: the last N converged matches are compared");
	write(c, s, "covariance_check_quantile", covariance_check_quantile,
		"covariance_check: this quantile of the matches' Mahalanobis^2 is made consistent");
}
}  // namespace featloc
