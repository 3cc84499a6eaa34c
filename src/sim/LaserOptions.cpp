#include "featloc/sim/LaserOptions.h"

#include "featloc/config/ConfigValues.h"

namespace featloc
{
namespace
{
struct Preset
{
	const char* name;
	unsigned int beams;
	double apertureDeg, maxRange, minRange, noise;
};
constexpr Preset kPresets[] = {
	{"sick_lms200_181", 181, 180, 80, 0.1, 0.01},
	{"sick_lms200_361", 361, 180, 80, 0.1, 0.01},
	{"ibeo_ladar_2d30", 541, 270, 30, 0.3, 0.025},
	{"hokuyo_utm30lx", 1081, 270, 30, 0.1, 0.015},
};
}  // namespace

bool LaserOptions::applyPreset(const std::string& name)
{
	for (const auto& p : kPresets)
		if (name == p.name)
		{
			preset = name;
			beams = p.beams;
			aperture = mrpt::DEG2RAD(p.apertureDeg);
			max_range = p.maxRange;
			min_range = p.minRange;
			range_noise = p.noise;
			return true;
		}
	return false;
}

std::vector<std::string> LaserOptions::presetNames()
{
	std::vector<std::string> n;
	for (const auto& p : kPresets) n.emplace_back(p.name);
	return n;
}

void LaserOptions::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	using namespace featloc::config;
	std::string name = preset;
	readChoice(c, s, "preset", name, presetNames());
	applyPreset(name);
	read(c, s, "label", label);
	read(c, s, "rate", rate);
	read(c, s, "beams", beams);
	readDegrees(c, s, "aperture_DEG", aperture);
	read(c, s, "max_range", max_range);
	read(c, s, "min_range", min_range);
	read(c, s, "range_noise", range_noise);
	read(c, s, "range_bias", range_bias);
	read(c, s, "range_step", range_step);
	read(c, s, "dropout_probability", dropout_probability);
	std::vector<double> pose = {
		sensor_pose[0], sensor_pose[1], mrpt::RAD2DEG(sensor_pose[2])};
	read(c, s, "sensor_pose", pose);
	require(pose.size() == 3, c, s, "sensor_pose", "[x y yaw_deg]");
	sensor_pose = {pose[0], pose[1], mrpt::DEG2RAD(pose[2])};

	require(!label.empty(), c, s, "label", "a non-empty sensor label");
	// Real 2-D lidars give at most a few thousand beams, some 100 scans a
	// second: far beyond is a typo that would fill memory and disk.
	require(rate > 0 && rate <= 1000, c, s, "rate", "in (0, 1000] Hz");
	require(beams >= 2 && beams <= 100000, c, s, "beams", "in [2, 100000]");
	require(aperture > 0 && aperture <= 2 * M_PI, c, s, "aperture_DEG", "in (0, 360]");
	require(max_range > 0, c, s, "max_range", "> 0");
	require(min_range >= 0 && min_range < max_range, c, s, "min_range",
		"in [0, max_range)");
	require(range_noise >= 0, c, s, "range_noise", ">= 0");
	require(range_step >= 0, c, s, "range_step", ">= 0 (0: none)");
	require(dropout_probability >= 0 && dropout_probability < 1, c, s,
		"dropout_probability", "in [0, 1)");
}

void LaserOptions::saveToConfigFile(
	mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	using namespace featloc::config;
	std::string names;
	for (const auto& n : presetNames()) names += (names.empty() ? "" : " | ") + n;
	write(c, s, "preset", preset, names + " (keys below override it)");
	write(c, s, "label", label, "sensor label in the rawlog");
	write(c, s, "rate", rate, "[Hz] scans per second");
	write(c, s, "beams", beams, "number of beams");
	writeDegrees(c, s, "aperture_DEG", aperture, "[deg] field of view");
	write(c, s, "max_range", max_range, "[m] farther: no return (invalid)");
	write(c, s, "min_range", min_range, "[m] nearer: invalid");
	write(c, s, "range_noise", range_noise, "[m] Gaussian range noise sigma");
	write(c, s, "range_bias", range_bias, "[m] added to every range");
	write(c, s, "range_step", range_step,
		"[m] the exact range is rounded to a multiple of this before the noise (0: none; MRPT's simulated log: 0.16)");
	write(c, s, "dropout_probability", dropout_probability,
		"a beam is invalid with this probability");
	write(c, s, "sensor_pose",
		std::vector<double>{sensor_pose[0], sensor_pose[1], mrpt::RAD2DEG(sensor_pose[2])},
		"[m m deg] sensor on the robot");
}
}  // namespace featloc
