#pragma once
#include <mrpt/config/CLoadableOptions.h>
#include <mrpt/core/bits_math.h>

#include <string>

namespace featloc
{
/** `[Ekf]`: the EKF front end (EkfLocalizer, estimator = ekf). */
struct EkfOptions : public mrpt::config::CLoadableOptions
{
	static constexpr const char* kSection = "Ekf";

	/** A scan-matcher motion whose Mahalanobis^2 against the prediction
	 * exceeds this is not used (21.1: 99.99% for 3 dof; a 99% gate
	 * drops about one good match in a hundred, and each costs accuracy in
	 * turns, where odometry is worst). */
	double matcher_gate_chi2 = 21.1;
	/** Fuse the scan matcher's motions (false: odometry and landmarks
	 * only, e.g. stereo landmarks alone). */
	bool use_scan_matcher = true;
	/** The matcher's covariance is scaled by this before fusion (1: as the
	 * matcher reports it; MRPT's ICP under-reports by about 2). */
	double matcher_covariance_scale = 1;
	/** Prior sigma [rad] of the odometry direction offset b
	 * (EkfLocalizer): the angle between the odometry's direction of travel
	 * and the scanner frame's, estimated from the matches. 0: not
	 * estimated (b = 0). Config key odometry_direction_sigma_DEG. 2 deg:
	 * chosen on MRPT's Malaga log (5 deg gated a good match out there),
	 * then measured on the Radish logs with their wheel odometry
	 * (doc/benchmarks.md, "Gates and odometry covariance"). */
	double odometry_direction_sigma = mrpt::DEG2RAD(2.0);
	/** Probability of the landmark gates: individual (2 dof) and joint
	 * (2 dof per pair). */
	double landmark_gate_probability = 0.99;
	/** An unidentified observation starts a new landmark only when it lies
	 * outside this (2 dof) probability gate of every landmark; between the
	 * two gates it is ignored as ambiguous. */
	double landmark_new_probability = 0.99999;
	/** jcbb (joint compatibility branch and bound) | nearest (each
	 * observation its nearest compatible landmark). */
	std::string data_association = "jcbb";
	/** Vertical-line (stereo) landmarks used per frame: the least
	 * uncertain of those paired (Moon, Miura & Shirai, section 4). */
	unsigned int stereo_landmarks_per_frame = 10;
	/** A landmark seen only once is removed after this many frames of its
	 * own sensor (range-bearing frames or stereo pairs), whatever the EKF
	 * steps between them (a 40 Hz laser between 2.5 Hz pairs). */
	unsigned int landmark_probation_steps = 10;

	void loadFromConfigFile(
		const mrpt::config::CConfigFileBase& c, const std::string& s) override;
	void saveToConfigFile(
		mrpt::config::CConfigFileBase& c, const std::string& s) const override;
};
}  // namespace featloc
