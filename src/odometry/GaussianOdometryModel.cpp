#include "featloc/odometry/GaussianOdometryModel.h"

#include "featloc/config/ConfigValues.h"

namespace featloc
{
mrpt::obs::CActionRobotMovement2D::TMotionModelOptions
	GaussianOdometryModel::motionModel() const
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

mrpt::poses::CPosePDFGaussian GaussianOdometryModel::incrementPdf(
	const mrpt::poses::CPose2D& increment) const
{
	mrpt::obs::CActionRobotMovement2D a;
	a.computeFromOdometry(increment, motionModel());
	mrpt::poses::CPosePDFGaussian g;
	g.copyFrom(*a.poseChange);
	return g;
}

void GaussianOdometryModel::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	using namespace featloc::config;
	read(c, s, "sigma_xy_min", sigma_xy_min);
	read(c, s, "sigma_xy_per_m", sigma_xy_per_m);
	// Per degree in the file, per radian in memory.
	double perDeg = sigma_xy_per_rad * mrpt::DEG2RAD(1.0);
	read(c, s, "sigma_xy_per_deg", perDeg);
	sigma_xy_per_rad = perDeg / mrpt::DEG2RAD(1.0);
	readDegrees(c, s, "sigma_yaw_min_DEG", sigma_yaw_min);
	readDegrees(c, s, "sigma_yaw_per_m_DEG", sigma_yaw_per_m);
	read(c, s, "sigma_yaw_per_deg", sigma_yaw_per_rad);	// deg/deg == rad/rad

	require(sigma_xy_min > 0, c, s, "sigma_xy_min", "> 0");
	require(sigma_xy_per_m >= 0, c, s, "sigma_xy_per_m", ">= 0");
	require(sigma_xy_per_rad >= 0, c, s, "sigma_xy_per_deg", ">= 0");
	require(sigma_yaw_min > 0, c, s, "sigma_yaw_min_DEG", "> 0");
	require(sigma_yaw_per_m >= 0, c, s, "sigma_yaw_per_m_DEG", ">= 0");
	require(sigma_yaw_per_rad >= 0, c, s, "sigma_yaw_per_deg", ">= 0");
}

void GaussianOdometryModel::saveToConfigFile(
	mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	using namespace featloc::config;
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
}
}  // namespace featloc
