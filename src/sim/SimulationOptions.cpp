#include "featloc/sim/SimulationOptions.h"

#include "featloc/config/ConfigValues.h"

namespace featloc
{
void SimulationOptions::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	using namespace featloc::config;
	read(c, s, "t0", t0);
	read(c, s, "duration", duration);
	read(c, s, "max_scans", max_scans);
	read(c, s, "seed", seed);
	read(c, s, "format", format);
	read(c, s, "compress", compress);
	require(t0 > 0, c, s, "t0", "> 0 (a valid MRPT timestamp)");
	require(duration >= 0, c, s, "duration", ">= 0");
	require(format == 1 || format == 2, c, s, "format", "1 or 2");
}

void SimulationOptions::saveToConfigFile(
	mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	using namespace featloc::config;
	write(c, s, "t0", t0, "[s] UNIX time of the first scan");
	write(c, s, "duration", duration, "[s] 0 = until the robot's path ends");
	write(c, s, "max_scans", max_scans, "0 = no limit");
	write(c, s, "seed", seed, "random seed (--seed overrides)");
	write(c, s, "format", format, "rawlog format: 1 (actions + frames) or 2 (observations)");
	write(c, s, "compress", compress, "gzip the rawlog");
}
}  // namespace featloc
