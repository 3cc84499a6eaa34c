#include "featloc/live/LiveSensor.h"

#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/hwdrivers/CGenericSensor.h>
#include <mrpt/obs/CObservation.h>

#include <algorithm>
#include <cctype>

#include "featloc/config/TrackedConfig.h"
#include "featloc/core/ConfigError.h"

namespace featloc
{
namespace
{
/** The message of an MRPT exception without its call stack. */
std::string driverMessage(const std::exception& e)
{
	std::string text = e.what();
	const auto m = text.find("Message:");
	if (m != std::string::npos) text = text.substr(m + 8);
	const auto end = text.find("\nLocation:");
	if (end != std::string::npos) text = text.substr(0, end);
	text.erase(0, text.find_first_not_of(" \n\t"));
	while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.pop_back();
	return text;
}

/** Keys that say where a device is: addresses, ports, serial devices. */
std::string addressKeys(const mrpt::config::CConfigFileBase& cfg, const std::string& section)
{
	std::vector<std::string> keys;
	cfg.getAllKeys(section, keys);
	std::string out;
	for (const auto& k : keys)
	{
		std::string lower = k;
		std::transform(lower.begin(), lower.end(), lower.begin(), ::tolower);
		if (lower.find("ip") != std::string::npos || lower.find("port") != std::string::npos ||
			lower.find("host") != std::string::npos || lower.find("com_") != std::string::npos ||
			lower.find("serial") != std::string::npos || lower.find("device") != std::string::npos)
			out += (out.empty() ? "" : " ") + k + "=" + cfg.read_string(section, k, "");
	}
	return out.empty() ? "no address key" : out;
}
}  // namespace

LiveSensor::LiveSensor(const TrackedConfig& cfg, std::string section, size_t index,
	double restartPause, Sink sink)
	: m_section(std::move(section)),
	  m_index(index),
	  m_restartPause(restartPause),
	  m_sink(std::move(sink)),
	  m_config(std::make_unique<mrpt::config::CConfigFileMemory>(cfg.content()))
{
	m_driverName = cfg.read_string(m_section, "driver", "");
	const std::string where = cfg.sourceName() + ": [" + m_section + "]";
	if (m_driverName.empty())
		throw ConfigError(where + ": no 'driver' key (e.g. driver = CHokuyoURG)");
	m_address = addressKeys(*m_config, m_section);
	try
	{
		// Through the tracked config: the keys the driver reads are known.
		m_driver = makeDriver(cfg);
	}
	catch (const ConfigError&)
	{
		throw;
	}
	catch (const std::exception& e)
	{
		throw ConfigError(where + " driver " + m_driverName + ": " + driverMessage(e));
	}
}

LiveSensor::~LiveSensor() { stop(); }

std::shared_ptr<mrpt::hwdrivers::CGenericSensor> LiveSensor::makeDriver(
	const mrpt::config::CConfigFileBase& cfg) const
{
	auto driver = mrpt::hwdrivers::CGenericSensor::createSensorPtr(m_driverName);
	if (!driver)
		throw ConfigError("[" + m_section + "] driver = " + m_driverName +
			": not an MRPT sensor driver (e.g. CHokuyoURG, CLMS100Eth, CSickLaserSerial, "
			"CCameraSensor, or featloc's TcpOdometrySensor; names are case-sensitive)");
	driver->loadConfig(cfg, m_section);
	return driver;
}

void LiveSensor::start()
{
	m_startedAt = std::chrono::steady_clock::now();
	m_thread = std::thread([this] { run(); });
}

void LiveSensor::stop()
{
	m_stop = true;
	if (m_thread.joinable()) m_thread.join();
}

LiveSensor::Status LiveSensor::status() const
{
	std::lock_guard<std::mutex> lock(m_statusMutex);
	return m_status;
}

void LiveSensor::run()
{
	bool initialized = false;
	while (!m_stop)
	{
		try
		{
			if (!m_driver) m_driver = makeDriver(*m_config);
			if (!initialized)
			{
				m_driver->initialize();
				initialized = true;
			}
			m_driver->doProcess();
			const auto objects = m_driver->getObservations();
			for (const auto& [t, object] : objects)
			{
				auto obs = std::dynamic_pointer_cast<mrpt::obs::CObservation>(object);
				if (!obs) continue;
				m_sink({m_index, obs, std::chrono::steady_clock::now()});
				std::lock_guard<std::mutex> lock(m_statusMutex);
				m_status.received++;
				m_status.delivered = true;
			}
			if (objects.empty()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
		}
		catch (const std::exception& e)
		{
			{
				std::lock_guard<std::mutex> lock(m_statusMutex);
				m_status.failures++;
				m_status.lastError = driverMessage(e);
			}
			m_driver.reset();
			initialized = false;
			const auto until = std::chrono::steady_clock::now() +
				std::chrono::duration_cast<std::chrono::steady_clock::duration>(
					std::chrono::duration<double>(m_restartPause));
			while (!m_stop && std::chrono::steady_clock::now() < until)
				std::this_thread::sleep_for(std::chrono::milliseconds(10));
		}
	}
	m_driver.reset();  // the driver's destructor switches the device off
}
}  // namespace featloc
