#include "featloc/ekf/EkfOptions.h"

#include <cmath>

#include "featloc/config/ConfigValues.h"

namespace featloc
{
void EkfOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	using namespace featloc::config;
	read(c, s, "use_scan_matcher", use_scan_matcher);
	read(c, s, "matcher_gate_chi2", matcher_gate_chi2);
	read(c, s, "matcher_covariance_scale", matcher_covariance_scale);
	readDegrees(c, s, "odometry_direction_sigma_DEG", odometry_direction_sigma);
	read(c, s, "landmark_gate_probability", landmark_gate_probability);
	read(c, s, "landmark_new_probability", landmark_new_probability);
	readChoice(c, s, "data_association", data_association, {"jcbb", "nearest"});
	read(c, s, "stereo_landmarks_per_frame", stereo_landmarks_per_frame);
	read(c, s, "landmark_probation_steps", landmark_probation_steps);
	require(matcher_gate_chi2 > 0, c, s, "matcher_gate_chi2", "> 0");
	require(matcher_covariance_scale > 0, c, s, "matcher_covariance_scale", "> 0");
	require(odometry_direction_sigma >= 0 && odometry_direction_sigma <= M_PI / 4, c, s,
		"odometry_direction_sigma_DEG", "in [0, 45]");
	require(landmark_gate_probability > 0 && landmark_gate_probability < 1, c, s,
		"landmark_gate_probability", "in (0, 1)");
	require(landmark_new_probability >= landmark_gate_probability && landmark_new_probability < 1,
		c, s, "landmark_new_probability", "in [landmark_gate_probability, 1)");
}

void EkfOptions::saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	using namespace featloc::config;
	write(c, s, "use_scan_matcher", use_scan_matcher,
		"fuse the scan matcher's motions (false: odometry and landmarks only)");
	write(c, s, "matcher_gate_chi2", matcher_gate_chi2,
		"a matcher motion whose Mahalanobis^2 against the prediction exceeds this is not used (21.1: 99.99% for 3 dof)");
	write(c, s, "matcher_covariance_scale", matcher_covariance_scale,
		"the matcher's covariance times this before fusion");
	writeDegrees(c, s, "odometry_direction_sigma_DEG", odometry_direction_sigma,
		"prior sigma of the angle between the odometry's direction of travel and the scanner's, estimated from the matches (0: not estimated)");
	write(c, s, "landmark_gate_probability", landmark_gate_probability,
		"probability of the individual and joint landmark gates (chi-square)");
	write(c, s, "landmark_new_probability", landmark_new_probability,
		"an unidentified observation outside this gate of every landmark starts a new one");
	write(c, s, "data_association", data_association,
		"jcbb (joint compatibility branch and bound) | nearest");
	write(c, s, "stereo_landmarks_per_frame", stereo_landmarks_per_frame,
		"vertical-line (stereo) landmarks used per frame: the least uncertain of those paired");
	write(c, s, "landmark_probation_steps", landmark_probation_steps,
		"a landmark seen only once is removed after this many frames of its sensor "
		"(range-bearing frames or stereo pairs; not EKF steps)");
}
}  // namespace featloc
