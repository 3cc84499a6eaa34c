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
	/** [s] A driver that has delivered and then sends nothing this long,
	 * without an error, is restarted too (a device that hangs with its
	 * link up); 0: never. */
	double restart_after_silence = 5;
	/** [s] A driver call (doProcess, a driver's destruction) lasting this
	 * long is stuck: its thread is left behind and a new driver started
	 * (initialize() gets startup_timeout). MRPT 2.5.8's TCP drivers can
	 * loop forever in CClientTCPSocket::writeAsync once a device has reset
	 * the connection. At stop, drivers get this long to finish. */
	double driver_stuck_timeout = 10;
	/** When a sensor that replays a recording (CCameraSensor with
	 * grabber_type = rawlog) delivers each observation
	 * (RecordingReplayClock): "now" (the first at once, the others at
	 * their recorded intervals, re-stamped) or "recorded" (at its own
	 * stamp, read as this computer's clock: featloc-sim --serve's camera
	 * recording). */
	std::string replay_clock = "now";

	/** Every section with a `driver` key: the sensors a configuration
	 * describes, run or not. */
	static std::vector<std::string> sensorSections(const mrpt::config::CConfigFileBase& c);

	void loadFromConfigFile(
		const mrpt::config::CConfigFileBase& c, const std::string& s) override;
	void saveToConfigFile(
		mrpt::config::CConfigFileBase& c, const std::string& s) const override;
};
}  // namespace featloc
