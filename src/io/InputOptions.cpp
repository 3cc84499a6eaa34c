#include "featloc/io/InputOptions.h"

#include "featloc/config/ConfigValues.h"

namespace featloc
{
void InputOptions::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	using namespace featloc::config;
	read(c, s, "rawlog", rawlog);
	read(c, s, "laser_label", laser_label);
	readChoice(
		c, s, "invalid_range_policy", invalid_range_policy,
		{"error", "invalidate"});
	read(c, s, "max_scans", max_scans);
	readChoice(c, s, "carmen_beam_angles", carmen_beam_angles, {"sick", "even"});
}

void InputOptions::saveToConfigFile(
	mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	using namespace featloc::config;
	write(c, s, "rawlog", rawlog,
		"rawlog file (.rawlog, gz or plain); relative to this ini's folder");
	write(c, s, "laser_label", laser_label,
		"sensor label of the 2-D laser; empty = the log's only laser");
	write(c, s, "invalid_range_policy", invalid_range_policy,
		"error | invalidate: beams marked valid with NaN/Inf/negative range");
	write(c, s, "max_scans", max_scans,
		"stop after this many scans (0 = whole log)");
	write(c, s, "carmen_beam_angles", carmen_beam_angles,
		"CARMEN logs: sick (FLASER beams from -90 deg, 1 / 0.5 / 0.25 deg apart: 180 beams end at "
		"+89 deg) | even (n beams over -90..+90 deg, MRPT's carmen2rawlog)");
}
}  // namespace featloc
