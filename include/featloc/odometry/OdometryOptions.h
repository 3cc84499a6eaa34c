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

	/** Format #2: a scan up to this long [s] after the newest odometry
	 * reading takes the last two readings' motion continued at constant
	 * velocity, instead of waiting for a reading after it (0: always wait
	 * and interpolate). Live runs: the pose does not wait for the next
	 * reading (one reading period, 10 ms at 100 Hz); decided on the
	 * sequence of entries alone, so a replay of live.rawlog does the same. */
	double max_extrapolation = 0;

	/** Prior for a step without odometry: "constant_velocity", the
	 * estimate's velocity over the last no_odometry_velocity_window seconds
	 * continued (ConstantVelocityPrior; zero motion until the window has
	 * poses), or "zero" motion; with these standard deviations. */
	std::string no_odometry_prior = "constant_velocity";
	double no_odometry_velocity_window = 0.5;  //!< [s]
	double no_odometry_sigma_xy = 1.0;	//!< [m]
	double no_odometry_sigma_yaw = mrpt::DEG2RAD(30.0);	//!< [rad]

	/** Format #1 odometry may have been read anywhere within the interval
	 * between two scans: the matchers' guess gates allow for the resulting
	 * offset at both ends of a match (OdometrySamplingOffset), and the EKF
	 * keeps each reading's offset in its state (EkfLocalizer::predict), so
	 * its gate and its weights both allow for it. */
	bool action_sampling_offset = true;

	/** Check the odometry covariance against the scan matches as the run
	 * goes and inflate it when the log's (or the model's) is too small for
	 * the disagreements seen (OdometryCovarianceCheck). Off by default:
	 * where a matcher is confidently wrong (ICP along a corridor) the check
	 * blames odometry and weakens the gate that caught it, and on the logs
	 * it was meant for, action_sampling_offset does its job
	 * (doc/benchmarks.md). */
	bool covariance_check = false;
	/** The check uses the last this many converged matches. */
	unsigned int covariance_check_window = 100;
	/** The check makes this quantile of the matches' Mahalanobis^2 against
	 * odometry consistent (0.5: the median; higher: also the tails of the
	 * odometry error, at the cost of robustness to wrong matches). */
	double covariance_check_quantile = 0.9;

	void loadFromConfigFile(
		const mrpt::config::CConfigFileBase& c,
		const std::string& s) override;
	void saveToConfigFile(
		mrpt::config::CConfigFileBase& c, const std::string& s) const override;
};
}  // namespace featloc
