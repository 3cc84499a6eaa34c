#include "featloc/sim/SimOdometryOptions.h"

#include "featloc/config/ConfigValues.h"

namespace featloc
{
mrpt::obs::CActionRobotMovement2D::TMotionModelOptions
	SimOdometryOptions::thrunModel() const
{
	mrpt::obs::CActionRobotMovement2D::TMotionModelOptions o;
	o.modelSelection = mrpt::obs::CActionRobotMovement2D::mmThrun;
	auto& th = o.thrunModel;
	th.alfa1_rot_rot = static_cast<float>(thrun_alpha1_rot_rot);
	th.alfa2_rot_trans = static_cast<float>(thrun_alpha2_rot_trans);
	th.alfa3_trans_trans = static_cast<float>(thrun_alpha3_trans_trans);
	th.alfa4_trans_rot = static_cast<float>(thrun_alpha4_trans_rot);
	th.additional_std_XY = static_cast<float>(thrun_additional_std_xy);
	th.additional_std_phi = static_cast<float>(thrun_additional_std_yaw);
	return o;
}

void SimOdometryOptions::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	using namespace featloc::config;
	readChoice(c, s, "mode", mode, {"model", "perturbed_pairs"});
	readChoice(c, s, "model", model, {"gaussian", "thrun"});
	gaussian.loadFromConfigFile(c, s);
	read(c, s, "thrun_alpha1_rot_rot", thrun_alpha1_rot_rot);
	double a2 = mrpt::RAD2DEG(thrun_alpha2_rot_trans);
	read(c, s, "thrun_alpha2_rot_trans_DEG_per_m", a2);
	thrun_alpha2_rot_trans = mrpt::DEG2RAD(a2);
	read(c, s, "thrun_alpha3_trans_trans", thrun_alpha3_trans_trans);
	double a4 = mrpt::DEG2RAD(thrun_alpha4_trans_rot);
	read(c, s, "thrun_alpha4_trans_rot_m_per_deg", a4);
	thrun_alpha4_trans_rot = mrpt::RAD2DEG(a4);
	read(c, s, "thrun_additional_std_xy", thrun_additional_std_xy);
	readDegrees(c, s, "thrun_additional_std_yaw_DEG", thrun_additional_std_yaw);
	readChoice(c, s, "perturbation", perturbation, {"uniform", "gaussian"});
	read(c, s, "perturbation_xy", perturbation_xy);
	readDegrees(c, s, "perturbation_yaw_DEG", perturbation_yaw);
	read(c, s, "rate", rate);
	for (const char* k :
		 {"thrun_alpha1_rot_rot", "thrun_alpha2_rot_trans_DEG_per_m",
		  "thrun_alpha3_trans_trans", "thrun_alpha4_trans_rot_m_per_deg",
		  "thrun_additional_std_xy", "thrun_additional_std_yaw_DEG",
		  "perturbation_xy", "perturbation_yaw_DEG"})
	{
		double v = 0;
		read(c, s, k, v);
		require(v >= 0, c, s, k, ">= 0");
	}
	require(rate > 0, c, s, "rate", "> 0");
}

void SimOdometryOptions::saveToConfigFile(
	mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	using namespace featloc::config;
	write(c, s, "mode", mode, "model | perturbed_pairs");
	write(c, s, "model", model, "gaussian | thrun (mode = model)");
	gaussian.saveToConfigFile(c, s);
	write(c, s, "thrun_alpha1_rot_rot", thrun_alpha1_rot_rot,
		"[rad/rad] thrun: rotation noise per rotation");
	write(c, s, "thrun_alpha2_rot_trans_DEG_per_m", mrpt::RAD2DEG(thrun_alpha2_rot_trans),
		"[deg/m] thrun: rotation noise per metre");
	write(c, s, "thrun_alpha3_trans_trans", thrun_alpha3_trans_trans,
		"[m/m] thrun: translation noise per metre");
	write(c, s, "thrun_alpha4_trans_rot_m_per_deg", mrpt::DEG2RAD(thrun_alpha4_trans_rot),
		"[m/deg] thrun: translation noise per degree");
	write(c, s, "thrun_additional_std_xy", thrun_additional_std_xy,
		"[m] thrun: additive xy noise");
	writeDegrees(c, s, "thrun_additional_std_yaw_DEG", thrun_additional_std_yaw,
		"[deg] thrun: additive yaw noise");
	write(c, s, "perturbation", perturbation,
		"uniform | gaussian (mode = perturbed_pairs)");
	write(c, s, "perturbation_xy", perturbation_xy,
		"[m] perturbed_pairs: half-width (uniform) or sigma per axis");
	writeDegrees(c, s, "perturbation_yaw_DEG", perturbation_yaw,
		"[deg] perturbed_pairs: half-width or sigma");
	write(c, s, "rate", rate, "[Hz] format #2: odometry readings per second");
}
}  // namespace featloc
