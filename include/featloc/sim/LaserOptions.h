#pragma once
#include <mrpt/config/CLoadableOptions.h>
#include <mrpt/core/bits_math.h>

#include <string>
#include <vector>

namespace featloc
{
/** `[Laser]` of a world file: the simulated 2-D range finder.
 *
 * A preset sets the geometry and noise of a real sensor; any key given
 * after it overrides the preset's value:
 *
 * | preset          | beams | aperture | max range | min range | noise sigma |
 * |-----------------|-------|----------|-----------|-----------|-------------|
 * | sick_lms200_181 | 181   | 180 deg  | 80 m      | 0.1 m     | 0.01 m      |
 * | sick_lms200_361 | 361   | 180 deg  | 80 m      | 0.1 m     | 0.01 m      |
 * | ibeo_ladar_2d30 | 541   | 270 deg  | 30 m      | 0.3 m     | 0.025 m     |
 * | hokuyo_utm30lx  | 1081  | 270 deg  | 30 m      | 0.1 m     | 0.015 m     |
 *
 * (SICK: 0.01 m as specified for the CF-IDC experiments; IBEO Ladar 2D30:
 * "+-5 cm" in Borges & Aldon, taken as 2 sigma; Hokuyo UTM-30LX: datasheet
 * accuracy +-30 mm below 10 m, taken as 2 sigma.)
 *
 * Each range is rounded to a multiple of range_step (0: not), then gets
 * bias + Gaussian noise; a beam drops out (invalid) with
 * dropout_probability; readings at or beyond max_range (no return) and
 * below min_range are marked invalid. */
struct LaserOptions : public mrpt::config::CLoadableOptions
{
	static constexpr const char* kSection = "Laser";

	std::string preset = "sick_lms200_361";
	std::string label = "LASER";  //!< sensor label in the rawlog
	double rate = 10;  //!< [Hz] scans per second
	unsigned int beams = 361;
	double aperture = M_PI;	 //!< [rad]
	double max_range = 80;	//!< [m]
	double min_range = 0.1;	 //!< [m]
	double range_noise = 0.01;	//!< [m] Gaussian sigma
	double range_bias = 0;	//!< [m]
	/** [m] the exact range is rounded to a multiple of this before the
	 * noise is added (0: none): a range lattice, as MRPT's simulated log
	 * has (0.16 m) and some real logs (5 cm). */
	double range_step = 0;
	double dropout_probability = 0;
	/** Sensor on the robot: x [m], y [m], yaw [rad] (degrees in the file). */
	std::vector<double> sensor_pose = {0.2, 0, 0};

	/** Sets the preset's geometry and noise; false for an unknown name. */
	bool applyPreset(const std::string& name);
	static std::vector<std::string> presetNames();

	void loadFromConfigFile(
		const mrpt::config::CConfigFileBase& c,
		const std::string& s) override;
	void saveToConfigFile(
		mrpt::config::CConfigFileBase& c, const std::string& s) const override;
};
}  // namespace featloc
