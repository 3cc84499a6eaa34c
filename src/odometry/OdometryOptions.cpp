#include "featloc/odometry/OdometryOptions.h"

#include <mrpt/core/bits_math.h>

#include "featloc/config/ConfigValues.h"

namespace featloc
{
mrpt::obs::CActionRobotMovement2D::TMotionModelOptions
	OdometryOptions::motionModel() const
{
	mrpt::obs::CActionRobotMovement2D::TMotionModelOptions o;
	o.modelSelection = mrpt::obs::CActionRobotMovement2D::mmGaussian;
	o.gaussianModel.minStdXY = sigma_xy_min;
	o.gaussianModel.a1 = sigma_xy_per_m;
	o.gaussianModel.a2 = sigma_xy_per_rad;
	o.gaussianModel.minStdPHI = sigma_yaw_min;
	o.gaussianModel.a3 = sigma_yaw_per_m;
	o.gaussianModel.a4 = sigma_yaw_per_rad;
	return o;
}

void OdometryOptions::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	using namespace featloc::config;
	readChoice(c, s, "covariance_source", covariance_source, {"rawlog", "model"});
	read(c, s, "sigma_xy_min", sigma_xy_min);
	read(c, s, "sigma_xy_per_m", sigma_xy_per_m);
	// Per degree in the file, per radian in memory.
	double perDeg = sigma_xy_per_rad * mrpt::DEG2RAD(1.0);
	read(c, s, "sigma_xy_per_deg", perDeg);
	sigma_xy_per_rad = perDeg / mrpt::DEG2RAD(1.0);
	readDegrees(c, s, "sigma_yaw_min_DEG", sigma_yaw_min);
	readDegrees(c, s, "sigma_yaw_per_m_DEG", sigma_yaw_per_m);
	read(c, s, "sigma_yaw_per_deg", sigma_yaw_per_rad);	// deg/deg == rad/rad
	read(c, s, "max_interpolation_gap", max_interpolation_gap);
	read(c, s, "no_odometry_sigma_xy", no_odometry_sigma_xy);
	readDegrees(c, s, "no_odometry_sigma_yaw_DEG", no_odometry_sigma_yaw);

	for (const char* k :
		 {"sigma_xy_min", "sigma_xy_per_m", "sigma_xy_per_deg",
		  "sigma_yaw_min_DEG", "sigma_yaw_per_m_DEG", "sigma_yaw_per_deg"})
	{
		double v = 0;
		read(c, s, k, v);
		require(v >= 0, c, s, k, ">= 0");
	}
	require(sigma_xy_min > 0, c, s, "sigma_xy_min", "> 0");
	require(sigma_yaw_min > 0, c, s, "sigma_yaw_min_DEG", "> 0");
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
	write(c, s, "sigma_xy_min", sigma_xy_min, "[m] model: base xy sigma");
	write(c, s, "sigma_xy_per_m", sigma_xy_per_m,
		"[m/m] model: xy sigma per metre travelled");
	write(c, s, "sigma_xy_per_deg", sigma_xy_per_rad * mrpt::DEG2RAD(1.0),
		"[m/deg] model: xy sigma per degree turned");
	writeDegrees(c, s, "sigma_yaw_min_DEG", sigma_yaw_min,
		"[deg] model: base yaw sigma");
	writeDegrees(c, s, "sigma_yaw_per_m_DEG", sigma_yaw_per_m,
		"[deg/m] model: yaw sigma per metre travelled");
	write(c, s, "sigma_yaw_per_deg", sigma_yaw_per_rad,
		"[deg/deg] model: yaw sigma per degree turned");
	write(c, s, "max_interpolation_gap", max_interpolation_gap,
		"[s] format #2: max gap between odometry readings to interpolate");
	write(c, s, "no_odometry_sigma_xy", no_odometry_sigma_xy,
		"[m] prior sigma of a step without odometry (zero motion)");
	writeDegrees(c, s, "no_odometry_sigma_yaw_DEG", no_odometry_sigma_yaw,
		"[deg] prior yaw sigma of a step without odometry");
}
}  // namespace featloc
