#pragma once
#include <mrpt/obs/obs_frwds.h>

#include <atomic>
#include <chrono>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "featloc/live/LiveOptions.h"
#include "featloc/live/RecordingReplayClock.h"

namespace mrpt::hwdrivers
{
class CGenericSensor;
}
namespace mrpt::config
{
class CConfigFileBase;
class CConfigFileMemory;
}  // namespace mrpt::config

namespace featloc
{
class TrackedConfig;

/** One MRPT driver running in its own thread, as rawlog-grabber runs it:
 * `CGenericSensor::createSensorPtr(driver)`, `loadConfig(cfg, section)`,
 * `initialize()`, then `doProcess()` / `getObservations()` in a loop; every
 * observation goes to the sink as it comes.
 *
 * A driver that throws (a device sending garbage, a link that drops) is
 * logged, destroyed and started again from its section after a pause, so
 * one bad device never stops the run; what it had delivered is kept.
 *
 * A driver that never returns from a call is left behind: MRPT 2.5.8's
 * CClientTCPSocket::writeAsync() loops forever once the device has reset
 * the connection (select() says writable, send() fails, again), and
 * CHokuyoURG writes its commands with it. Such a thread cannot be stopped
 * or killed, so replaceStuckDriver() and stop() detach it (it keeps what it
 * uses and can deliver nothing more) and, mid-run, start a new driver. */
class LiveSensor
{
   public:
	struct Status
	{
		size_t received = 0;  //!< observations delivered
		size_t failures = 0;  //!< driver exceptions (each followed by a restart)
		std::string lastError;
		/** ERROR messages the driver logged itself (MRPT drivers log, and
		 * often retry, what they cannot read, e.g. a malformed frame). */
		size_t driverErrors = 0;
		std::string lastDriverError;
		/** Driver threads left behind, stuck inside a driver call. */
		size_t stuckDrivers = 0;
		bool delivered = false;	 //!< at least one observation
		/** [s] the longest time without an observation since the first
		 * one, and when it began (seconds after the first observation). */
		double longestGap = 0, longestGapStart = 0;
		/** A replayed recording (RecordingReplayClock): frames skipped,
		 * already overdue when read; and "" or why it ended (its end). */
		size_t skipped = 0;
		std::string ended;
	};
	struct Arrival
	{
		size_t sensor = 0;	//!< index in [Live] sensors
		std::shared_ptr<mrpt::obs::CObservation> observation;
		std::chrono::steady_clock::time_point arrival;
	};
	using Sink = std::function<void(Arrival)>;

	/** Makes the driver of `[section] driver` and loads its keys (reading
	 * them through `cfg`, so keys no driver reads are reported as
	 * unknown). Throws ConfigError naming the file and section for an
	 * unknown driver or keys the driver rejects. Nothing runs yet.
	 * `options`: restart_pause, restart_after_silence, replay_clock. */
	LiveSensor(const TrackedConfig& cfg, std::string section, size_t index,
		const LiveOptions& options, Sink sink);
	~LiveSensor();	//!< stop(0)
	LiveSensor(const LiveSensor&) = delete;
	LiveSensor& operator=(const LiveSensor&) = delete;

	void start();
	/** Asks the thread to stop and waits for it up to `timeout` [s] (a
	 * driver blocked in a read returns within its own timeout); one still
	 * inside the driver then is left behind. False when it was. */
	bool stop(double timeout);
	/** [s] how long the driver's current call (initialize, doProcess, its
	 * destruction) has lasted; 0 between calls. */
	double stuckFor() const;
	/** Whether that call is initialize() (CLMS100Eth alone sleeps ~15 s
	 * in it). */
	bool initializing() const;
	/** Leaves the current driver thread behind and starts a new driver
	 * (counted as a failure with `why`). */
	void replaceStuckDriver(const std::string& why);
	/** A driver call past 0.5 s gets the process's dead TCP connections
	 * freed (DeadConnectionRescue), at most every 0.5 s. */
	void rescueIfStuck();

	const std::string& section() const { return m_section; }
	/** "[SECTION] Driver", how messages name the sensor. */
	std::string label() const { return "[" + m_section + "] " + m_driverName; }
	const std::string& driver() const { return m_driverName; }
	/** The section's address keys ("IP_DIR=127.0.0.1 PORT_DIR=10940"),
	 * for messages about a device that does not answer. */
	const std::string& address() const { return m_address; }
	Status status() const;
	std::chrono::steady_clock::time_point startedAt() const { return m_startedAt; }

   private:
	struct Board;
	struct Worker;
	static std::shared_ptr<mrpt::hwdrivers::CGenericSensor> makeSensorDriver(
		const std::string& driverName, const std::string& section,
		const std::shared_ptr<Board>& board, const mrpt::config::CConfigFileBase& cfg);
	void launch(std::shared_ptr<mrpt::hwdrivers::CGenericSensor> driver);
	/** Detaches the current worker's thread, unable to deliver, and counts it. */
	void leaveBehind();

	std::string m_section, m_driverName, m_address;
	size_t m_index;
	double m_restartPause, m_restartAfterSilence;
	/** Set for a driver that replays a recording (DriverQuirks). */
	std::optional<RecordingReplayClock::Mode> m_replay;
	Sink m_sink;
	std::shared_ptr<mrpt::config::CConfigFileMemory> m_config;	//!< for restarts
	std::shared_ptr<mrpt::hwdrivers::CGenericSensor> m_firstDriver;	 //!< made by the constructor
	std::shared_ptr<Board> m_board;	 //!< shared with every worker, left behind or not
	std::shared_ptr<Worker> m_worker;
	std::thread m_thread;
	std::chrono::steady_clock::time_point m_startedAt;
	std::chrono::steady_clock::time_point m_lastRescue;	 //!< rescueIfStuck()
};
}  // namespace featloc
