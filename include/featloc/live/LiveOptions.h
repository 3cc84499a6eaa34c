#pragma once
#include <mrpt/config/CLoadableOptions.h>

#include <string>
#include <vector>

namespace featloc
{
/** `[Live]` of a featloc-live configuration: which sensor sections run
 * and how their observations are put in time order. Each sensor section
 * is in rawlog-grabber's style: `driver = CHokuyoURG` (any MRPT driver,
 * or featloc's TcpOdometrySensor) and that driver's own keys. */
struct LiveOptions : public mrpt::config::CLoadableOptions
{
	static constexpr const char* kSection = "Live";

	/** The sensor sections to run, e.g. "LASER ODOMETRY". */
	std::vector<std::string> sensors;
	/** [s] An observation is passed on once every other sensor has sent
	 * something later, or after this wait (a sensor that fell silent must
	 * not stall the others). One that arrives older than what was already
	 * passed on is "late": it is recorded apart (live-late.rawlog). */
	double max_wait = 0.1;
	/** [s] A sensor that has sent nothing this long after it was started
	 * is an error naming its section and address (a device that never
	 * answers). MRPT's CLMS100Eth alone needs ~15 s to start. */
	double startup_timeout = 30;
	/** [s] Period of the console status line (0: none). */
	double status_period = 1;
	/** [s] A driver whose exception ends doProcess() is restarted after
	 * this pause (a device sending garbage, a dropped link). */
	double restart_pause = 0.5;

	/** Every section with a `driver` key: the sensors a configuration
	 * describes, run or not. */
	static std::vector<std::string> sensorSections(const mrpt::config::CConfigFileBase& c);

	void loadFromConfigFile(
		const mrpt::config::CConfigFileBase& c, const std::string& s) override;
	void saveToConfigFile(
		mrpt::config::CConfigFileBase& c, const std::string& s) const override;
};
}  // namespace featloc
