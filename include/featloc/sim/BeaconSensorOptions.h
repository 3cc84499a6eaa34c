#pragma once
#include <mrpt/config/CLoadableOptions.h>
#include <mrpt/core/bits_math.h>

#include <string>
#include <vector>

namespace featloc
{
/** `[Beacons]` of a world file: point landmarks (reflectors, posts, the
 * stable visual landmarks a stereo head will give later) and the sensor
 * that measures their range and bearing. With no `points`, nothing is
 * simulated and the rawlog is as without this section.
 *
 * Each scan, every beacon within max_range, inside the field of view and
 * (with occlusion) not hidden by a wall, obstacle or person gives one
 * measurement: range + N(0, range_noise^2), bearing + N(0,
 * bearing_noise^2), written as a CObservationBearingRange with the scan's
 * time (in the scan's sensory frame in format #1, just before the scan in
 * format #2), its landmark ID when with_ids is set (-1 otherwise). */
struct BeaconSensorOptions : public mrpt::config::CLoadableOptions
{
	static constexpr const char* kSection = "Beacons";

	/** World positions [x y; ...] [m]. */
	std::vector<std::vector<double>> points;
	std::string label = "BEACONS";	//!< sensor label in the rawlog
	double max_range = 8;  //!< [m]
	double field_of_view = 2 * M_PI;  //!< [rad] centred on the heading
	double range_noise = 0.03;	//!< [m] Gaussian sigma
	double bearing_noise = mrpt::DEG2RAD(1.0);  //!< [rad] Gaussian sigma
	bool with_ids = false;	//!< the sensor knows which beacon it sees
	bool occlusion = true;	//!< walls, obstacles and people hide beacons
	/** Sensor on the robot: x [m], y [m], yaw [rad] (degrees in the file). */
	std::vector<double> sensor_pose = {0, 0, 0};

	bool enabled() const { return !points.empty(); }

	void loadFromConfigFile(
		const mrpt::config::CConfigFileBase& c, const std::string& s) override;
	void saveToConfigFile(
		mrpt::config::CConfigFileBase& c, const std::string& s) const override;
};
}  // namespace featloc
