#pragma once
#include <mrpt/config/CLoadableOptions.h>
#include <mrpt/core/bits_math.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/poses/CPosePDFGaussian.h>

namespace featloc
{
/** MRPT's Gaussian odometry error model (CActionRobotMovement2D,
 * mmGaussian), with its parameters named for what they are. For an
 * increment of length d and turn |dphi|:
 *   sigma_xy  = sigma_xy_min  + sigma_xy_per_m  * d + sigma_xy_per_deg  * |dphi|
 *   sigma_yaw = sigma_yaw_min + sigma_yaw_per_m * d + sigma_yaw_per_deg * |dphi|
 * and MRPT rotates the covariance to the middle of the turn. featloc-run
 * uses it as the belief about odometry, featloc-sim as the truth it
 * samples odometry errors from; both read the same keys. Defaults are
 * MRPT's own. */
struct GaussianOdometryModel : public mrpt::config::CLoadableOptions
{
	double sigma_xy_min = 0.01;	 //!< [m]
	double sigma_xy_per_m = 0.01;  //!< [m/m] (MRPT a1)
	double sigma_xy_per_rad = 0.001 / mrpt::DEG2RAD(1.0);  //!< [m/rad] (a2)
	double sigma_yaw_min = mrpt::DEG2RAD(0.2);	//!< [rad]
	double sigma_yaw_per_m = mrpt::DEG2RAD(1.0);  //!< [rad/m] (MRPT a3)
	double sigma_yaw_per_rad = 0.05;  //!< [rad/rad] (MRPT a4)

	/** The equivalent MRPT motion model options. */
	mrpt::obs::CActionRobotMovement2D::TMotionModelOptions motionModel() const;
	/** The increment with the model's covariance. */
	mrpt::poses::CPosePDFGaussian incrementPdf(
		const mrpt::poses::CPose2D& increment) const;

	void loadFromConfigFile(
		const mrpt::config::CConfigFileBase& c,
		const std::string& s) override;
	void saveToConfigFile(
		mrpt::config::CConfigFileBase& c, const std::string& s) const override;
};
}  // namespace featloc
