#pragma once
#include <mrpt/obs/obs_frwds.h>

#include <atomic>
#include <chrono>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

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
 * one bad device never stops the run; what it had delivered is kept. */
class LiveSensor
{
   public:
	struct Arrival
	{
		size_t sensor = 0;	//!< index in [Live] sensors
		std::shared_ptr<mrpt::obs::CObservation> observation;
		std::chrono::steady_clock::time_point arrival;
	};
	using Sink = std::function<void(Arrival)>;

	struct Status
	{
		size_t received = 0;  //!< observations delivered
		size_t failures = 0;  //!< driver exceptions (each followed by a restart)
		std::string lastError;
		bool delivered = false;	 //!< at least one observation
	};

	/** Makes the driver of `[section] driver` and loads its keys (reading
	 * them through `cfg`, so keys no driver reads are reported as
	 * unknown). Throws ConfigError naming the file and section for an
	 * unknown driver or keys the driver rejects. Nothing runs yet. */
	LiveSensor(const TrackedConfig& cfg, std::string section, size_t index,
		double restartPause, Sink sink);
	~LiveSensor();	//!< stops the thread
	LiveSensor(const LiveSensor&) = delete;
	LiveSensor& operator=(const LiveSensor&) = delete;

	void start();
	/** Asks the thread to stop and joins it (a driver blocked in a read
	 * returns within its own timeout). */
	void stop();

	const std::string& section() const { return m_section; }
	const std::string& driver() const { return m_driverName; }
	/** The section's address keys ("IP_DIR=127.0.0.1 PORT_DIR=10940"),
	 * for messages about a device that does not answer. */
	const std::string& address() const { return m_address; }
	Status status() const;
	std::chrono::steady_clock::time_point startedAt() const { return m_startedAt; }

   private:
	void run();
	std::shared_ptr<mrpt::hwdrivers::CGenericSensor> makeDriver(
		const mrpt::config::CConfigFileBase& cfg) const;

	std::string m_section, m_driverName, m_address;
	size_t m_index;
	double m_restartPause;
	Sink m_sink;
	std::unique_ptr<mrpt::config::CConfigFileMemory> m_config;	//!< for restarts
	std::shared_ptr<mrpt::hwdrivers::CGenericSensor> m_driver;
	std::atomic<bool> m_stop{false};
	std::thread m_thread;
	std::chrono::steady_clock::time_point m_startedAt;
	mutable std::mutex m_statusMutex;
	Status m_status;
};
}  // namespace featloc
