#pragma once
#include <mrpt/config/CLoadableOptions.h>
#include <mrpt/core/bits_math.h>

#include <string>

#include "featloc/odometry/GaussianOdometryModel.h"

namespace featloc
{
/** `[Odometry]` of a world file: the errors of the simulated odometry.
 *
 * mode = model: each increment (between consecutive scans in format #1,
 * between readings at `rate` in format #2) is the true increment with an
 * error drawn from MRPT's Gaussian model (same keys as featloc-run's
 * [Odometry]) or Thrun's model (CActionRobotMovement2D::mmThrun); the
 * rawlog carries the model's covariance. Errors accumulate like a real
 * robot's.
 *
 * mode = perturbed_pairs: each scan-to-scan increment is the true one plus
 * independent noise, uniform in [-a, a] or Gaussian with sigma a, per axis
 * (perturbation_xy, perturbation_yaw_DEG), and the rawlog carries that
 * noise's covariance: every scan pair is an independent trial of the
 * papers' protocols (Borges & Aldon: uniform +-0.3 m, +-10 deg). */
struct SimOdometryOptions : public mrpt::config::CLoadableOptions
{
	static constexpr const char* kSection = "Odometry";

	std::string mode = "model";	 //!< model | perturbed_pairs
	std::string model = "gaussian";	 //!< gaussian | thrun
	GaussianOdometryModel gaussian;
	// Thrun's model (MRPT TOptions_ThrunModel, defaults MRPT's).
	double thrun_alpha1_rot_rot = 0.05;	 //!< [rad/rad]
	double thrun_alpha2_rot_trans = mrpt::DEG2RAD(4.0);	 //!< [rad/m]
	double thrun_alpha3_trans_trans = 0.01;	 //!< [m/m]
	double thrun_alpha4_trans_rot = 0.0001 * 180 / M_PI;  //!< [m/rad]
	double thrun_additional_std_xy = 0.001;	 //!< [m]
	double thrun_additional_std_yaw = mrpt::DEG2RAD(0.05);	//!< [rad]
	std::string perturbation = "uniform";  //!< uniform | gaussian
	double perturbation_xy = 0.3;  //!< [m] half-width or sigma, per axis
	double perturbation_yaw = mrpt::DEG2RAD(10.0);	//!< [rad]
	double rate = 50;  //!< [Hz] format #2 readings (mode = model)

	/** MRPT options for Thrun's model with these parameters. */
	mrpt::obs::CActionRobotMovement2D::TMotionModelOptions thrunModel() const;

	void loadFromConfigFile(
		const mrpt::config::CConfigFileBase& c,
		const std::string& s) override;
	void saveToConfigFile(
		mrpt::config::CConfigFileBase& c, const std::string& s) const override;
};
}  // namespace featloc
