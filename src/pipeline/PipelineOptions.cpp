#include "featloc/pipeline/PipelineOptions.h"

#include <mrpt/core/bits_math.h>

#include "featloc/config/ConfigValues.h"
#include "featloc/core/ConfigError.h"
#include "featloc/estimators/PoseEstimatorFactory.h"

namespace featloc
{
void PipelineOptions::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	using namespace featloc::config;
	read(c, s, "estimator", estimator);
	try
	{
		PoseEstimatorFactory::create(estimator);
	}
	catch (const ConfigError& e)
	{
		fail(c, s, "estimator", e.what());
	}
	std::vector<double> pose = {
		initial_pose[0], initial_pose[1], mrpt::RAD2DEG(initial_pose[2])};
	read(c, s, "initial_pose", pose);
	require(pose.size() == 3, c, s, "initial_pose", "three numbers [x y yaw_deg]");
	initial_pose = {pose[0], pose[1], mrpt::DEG2RAD(pose[2])};
	read(c, s, "keyframe_distance", keyframe_distance);
	readDegrees(c, s, "keyframe_angle_DEG", keyframe_angle);
	require(keyframe_distance >= 0, c, s, "keyframe_distance", ">= 0");
	require(keyframe_angle >= 0, c, s, "keyframe_angle_DEG", ">= 0");
}

void PipelineOptions::saveToConfigFile(
	mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	using namespace featloc::config;
	write(c, s, "estimator", estimator,
		"odometry | matcher | ekf, or a class (featloc::EkfEstimator): how poses are "
		"estimated (ekf parameters: [Ekf])");
	write(c, s, "initial_pose",
		std::vector<double>{
			initial_pose[0], initial_pose[1], mrpt::RAD2DEG(initial_pose[2])},
		"[m m deg] robot pose at the first scan");
	write(c, s, "keyframe_distance", keyframe_distance,
		"[m] new reference scan after this motion (0 and angle 0: every scan)");
	writeDegrees(c, s, "keyframe_angle_DEG", keyframe_angle,
		"[deg] new reference scan after this rotation");
}
}  // namespace featloc
