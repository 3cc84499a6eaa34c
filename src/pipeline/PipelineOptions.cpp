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
	std::string text;
	global_start = readRaw(c, s, "initial_pose", text) && text == "global";
	if (!global_start)
	{
		read(c, s, "initial_pose", pose);
		require(pose.size() == 3, c, s, "initial_pose",
			"three numbers [x y yaw_deg], or global (find it in the [Localization] map)");
		initial_pose = {pose[0], pose[1], mrpt::DEG2RAD(pose[2])};
	}
	std::vector<double> sigma = {initial_pose_sigma[0], initial_pose_sigma[1],
		mrpt::RAD2DEG(initial_pose_sigma[2])};
	read(c, s, "initial_pose_sigma", sigma);
	require(sigma.size() == 3 && sigma[0] >= 0 && sigma[1] >= 0 && sigma[2] >= 0, c, s,
		"initial_pose_sigma", "three numbers >= 0 [sigma_x sigma_y sigma_yaw_deg]");
	initial_pose_sigma = {sigma[0], sigma[1], mrpt::DEG2RAD(sigma[2])};
	read(c, s, "keyframe_distance", keyframe_distance);
	readDegrees(c, s, "keyframe_angle_DEG", keyframe_angle);
	require(keyframe_distance >= 0, c, s, "keyframe_distance", ">= 0");
	require(keyframe_angle >= 0, c, s, "keyframe_angle_DEG", ">= 0");
	read(c, s, "failed_match_keeps_keyframe", failed_match_keeps_keyframe);
	read(c, s, "failed_match_keyframe_factor", failed_match_keyframe_factor);
	require(failed_match_keyframe_factor >= 1, c, s, "failed_match_keyframe_factor", ">= 1");
}

mrpt::poses::CPosePDFGaussian PipelineOptions::initialPose() const
{
	mrpt::math::CMatrixDouble33 cov;
	if (global_start)
	{
		cov(0, 0) = cov(1, 1) = kUnknownSigmaXY * kUnknownSigmaXY;
		cov(2, 2) = M_PI * M_PI;
		return mrpt::poses::CPosePDFGaussian(mrpt::poses::CPose2D(), cov);
	}
	for (int i = 0; i < 3; i++) cov(i, i) = initial_pose_sigma[i] * initial_pose_sigma[i];
	return mrpt::poses::CPosePDFGaussian(
		mrpt::poses::CPose2D(initial_pose[0], initial_pose[1], initial_pose[2]), cov);
}

void PipelineOptions::saveToConfigFile(
	mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	using namespace featloc::config;
	write(c, s, "estimator", estimator,
		"odometry | matcher | ekf, or a class (featloc::EkfEstimator): how poses are "
		"estimated (ekf parameters: [Ekf])");
	if (global_start)
		write(c, s, "initial_pose", std::string("global"),
			"unknown: found in the [Localization] map");
	else
		write(c, s, "initial_pose",
			std::vector<double>{initial_pose[0], initial_pose[1], mrpt::RAD2DEG(initial_pose[2])},
			"[m m deg] robot pose at the first scan, or global (found in the [Localization] map)");
	write(c, s, "initial_pose_sigma",
		std::vector<double>{initial_pose_sigma[0], initial_pose_sigma[1],
			mrpt::RAD2DEG(initial_pose_sigma[2])},
		"[m m deg] its standard deviations (0: the run's exact origin; in a known map: how well "
		"the start is known)");
	write(c, s, "keyframe_distance", keyframe_distance,
		"[m] new reference scan after this motion (0 and angle 0: every scan)");
	writeDegrees(c, s, "keyframe_angle_DEG", keyframe_angle,
		"[deg] new reference scan after this rotation");
	write(c, s, "failed_match_keeps_keyframe", failed_match_keeps_keyframe,
		"true: a failed match keeps the reference scan (the next good match corrects the "
		"failed steps); false: its scan becomes the reference");
	write(c, s, "failed_match_keyframe_factor", failed_match_keyframe_factor,
		"failed_match_keeps_keyframe: after a failed match the reference is replaced when the "
		"estimate's motion since it reaches this many times keyframe_distance / "
		"keyframe_angle_DEG (1: as after a good match)");
}
}  // namespace featloc
