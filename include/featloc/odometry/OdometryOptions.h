#pragma once
#include <mrpt/config/CLoadableOptions.h>
#include <mrpt/core/bits_math.h>
#include <mrpt/obs/CActionRobotMovement2D.h>

#include <string>

namespace featloc
{
/** `[Odometry]`: where odometry covariances come from and how odometry is
 * aligned with scan times.
 *
 * The error model is MRPT's Gaussian odometry model
 * (CActionRobotMovement2D::computeFromOdometry, mmGaussian): for an
 * increment of length d [m] and turn |dphi|,
 *   sigma_xy  = sigma_xy_min + sigma_xy_per_m * d + sigma_xy_per_deg * |dphi|
 *   sigma_yaw = sigma_yaw_min + sigma_yaw_per_m * d + sigma_yaw_per_deg * |dphi|
 * rotated to the middle of the turn. */
struct OdometryOptions : public mrpt::config::CLoadableOptions
{
	static constexpr const char* kSection = "Odometry";

	/** "rawlog": actions (format #1) keep the covariance stored in the log;
	 * "model": every increment gets the model's covariance. Odometry
	 * observations (format #2) carry no covariance and always use the
	 * model. */
	std::string covariance_source = "rawlog";

	// Defaults: MRPT's own TMotionModelOptions::TOptions_GaussianModel.
	double sigma_xy_min = 0.01;	 //!< [m]
	double sigma_xy_per_m = 0.01;  //!< [m/m] (MRPT a1)
	double sigma_xy_per_rad = 0.001 / mrpt::DEG2RAD(1.0);  //!< [m/rad] (a2)
	double sigma_yaw_min = mrpt::DEG2RAD(0.2);	//!< [rad]
	double sigma_yaw_per_m = mrpt::DEG2RAD(1.0);  //!< [rad/m] (MRPT a3)
	double sigma_yaw_per_rad = 0.05;  //!< [rad/rad] (MRPT a4)

	/** Format #2: odometry readings bracketing a scan are interpolated at
	 * the scan's time when at most this far apart [s]; otherwise the nearest
	 * reading within this distance is used; otherwise the step has no
	 * odometry. */
	double max_interpolation_gap = 0.5;

	/** Prior for a step without odometry: zero motion with these standard
	 * deviations. */
	double no_odometry_sigma_xy = 1.0;	//!< [m]
	double no_odometry_sigma_yaw = mrpt::DEG2RAD(30.0);	//!< [rad]

	/** The equivalent MRPT motion model options. */
	mrpt::obs::CActionRobotMovement2D::TMotionModelOptions motionModel() const;

	void loadFromConfigFile(
		const mrpt::config::CConfigFileBase& c,
		const std::string& s) override;
	void saveToConfigFile(
		mrpt::config::CConfigFileBase& c, const std::string& s) const override;
};
}  // namespace featloc
