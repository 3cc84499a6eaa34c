#include "featloc/live/LiveOptions.h"

#include <mrpt/system/string_utils.h>

#include "featloc/config/ConfigValues.h"

namespace featloc
{
std::vector<std::string> LiveOptions::sensorSections(const mrpt::config::CConfigFileBase& c)
{
	std::vector<std::string> sections, out;
	c.getAllSections(sections);
	for (const auto& s : sections)
	{
		std::vector<std::string> keys;
		c.getAllKeys(s, keys);
		for (const auto& k : keys)
			if (mrpt::system::lowerCase(k) == "driver") out.push_back(s);
	}
	return out;
}

void LiveOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	using namespace featloc::config;
	std::string list;
	read(c, s, "sensors", list);
	mrpt::system::tokenize(list, " \t", sensors);
	require(!sensors.empty(), c, s, "sensors",
		"the sensor sections to run, e.g. 'LASER ODOMETRY' (each with a driver key)");
	for (const auto& name : sensors)
		require(c.sectionExists(name), c, s, "sensors", "section [" + name + "] does not exist");
	read(c, s, "max_wait", max_wait);
	read(c, s, "startup_timeout", startup_timeout);
	read(c, s, "status_period", status_period);
	read(c, s, "restart_pause", restart_pause);
	read(c, s, "restart_after_silence", restart_after_silence);
	read(c, s, "driver_stuck_timeout", driver_stuck_timeout);
	read(c, s, "replay_clock", replay_clock);
	require(max_wait >= 0, c, s, "max_wait", ">= 0");
	require(startup_timeout > 0, c, s, "startup_timeout", "> 0");
	require(status_period >= 0, c, s, "status_period", ">= 0");
	require(restart_pause >= 0, c, s, "restart_pause", ">= 0");
	require(restart_after_silence >= 0, c, s, "restart_after_silence", ">= 0 (0: never)");
	require(driver_stuck_timeout > 0, c, s, "driver_stuck_timeout", "> 0");
	require(replay_clock == "now" || replay_clock == "recorded", c, s, "replay_clock",
		"now | recorded");
}

void LiveOptions::saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	using namespace featloc::config;
	std::string list;
	for (const auto& n : sensors) list += (list.empty() ? "" : " ") + n;
	write(c, s, "sensors", list,
		"sensor sections to run (rawlog-grabber style: driver = CHokuyoURG | CLMS100Eth | "
		"TcpOdometrySensor | ..., plus the driver's keys)");
	write(c, s, "max_wait", max_wait,
		"[s] an observation waits at most this long for the other sensors (time order)");
	write(c, s, "startup_timeout", startup_timeout,
		"[s] a sensor silent this long after its start is an error");
	write(c, s, "status_period", status_period, "[s] console status line period (0: none)");
	write(c, s, "restart_pause", restart_pause,
		"[s] pause before a failed driver is restarted");
	write(c, s, "restart_after_silence", restart_after_silence,
		"[s] a driver silent this long after delivering is restarted (0: never)");
	write(c, s, "driver_stuck_timeout", driver_stuck_timeout,
		"[s] a driver call lasting this long is stuck: left behind, a new driver started");
	write(c, s, "replay_clock", replay_clock,
		"a recording replayed as a sensor (CCameraSensor, grabber_type = rawlog): now (first "
		"frame at once, then its intervals, re-stamped) | recorded (at its stamps, this "
		"computer's clock)");
}
}  // namespace featloc
