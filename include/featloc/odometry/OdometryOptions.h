#pragma once
#include <mrpt/config/CLoadableOptions.h>
#include <mrpt/core/bits_math.h>

#include <string>

#include "featloc/odometry/GaussianOdometryModel.h"

namespace featloc
{
/** `[Odometry]` of featloc-run: where odometry covariances come from and
 * how odometry is aligned with scan times. The error model (the sigma_*
 * keys) is GaussianOdometryModel. */
struct OdometryOptions : public mrpt::config::CLoadableOptions
{
	static constexpr const char* kSection = "Odometry";

	/** "rawlog": actions (format #1) keep the covariance stored in the log;
	 * "model": every increment gets the model's covariance. Odometry
	 * observations (format #2) carry no covariance and always use the
	 * model. */
	std::string covariance_source = "rawlog";
	GaussianOdometryModel model;

	/** Format #2: odometry readings bracketing a scan are interpolated at
	 * the scan's time when at most this far apart [s]; otherwise the nearest
	 * reading within this distance is used; otherwise the step has no
	 * odometry. */
	double max_interpolation_gap = 0.5;

	/** Prior for a step without odometry: zero motion with these standard
	 * deviations. */
	double no_odometry_sigma_xy = 1.0;	//!< [m]
	double no_odometry_sigma_yaw = mrpt::DEG2RAD(30.0);	//!< [rad]

	void loadFromConfigFile(
		const mrpt::config::CConfigFileBase& c,
		const std::string& s) override;
	void saveToConfigFile(
		mrpt::config::CConfigFileBase& c, const std::string& s) const override;
};
}  // namespace featloc
