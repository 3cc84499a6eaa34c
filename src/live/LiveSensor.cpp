#include "featloc/live/LiveSensor.h"

#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/hwdrivers/CGenericSensor.h>
#include <mrpt/core/Clock.h>
#include <mrpt/obs/CObservation.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt/system/COutputLogger.h>

#include <unistd.h>

#include <algorithm>
#include <cctype>

#include "featloc/config/TrackedConfig.h"
#include "featloc/core/ConfigError.h"
#include "featloc/live/DeadConnectionRescue.h"
#include "featloc/live/DriverQuirks.h"

namespace featloc
{
namespace
{
/** The message of an MRPT exception without its call stack. */
std::string driverMessage(const std::exception& e)
{
	const std::string what = e.what();
	auto trimmed = [](std::string t) {
		t.erase(0, std::min(t.size(), t.find_first_not_of(" \n\t")));
		while (!t.empty() && std::isspace(static_cast<unsigned char>(t.back()))) t.pop_back();
		return t;
	};
	std::string text = what;
	const auto m = text.find("Message:");
	if (m != std::string::npos) text = text.substr(m + 8);
	const auto end = text.find("\nLocation:");
	if (end != std::string::npos) text = text.substr(0, end);
	text = trimmed(text);
	// A standard exception caught by MRPT_END has an empty message and its
	// text after "Location:" (e.g. a std::filesystem error).
	if (text.empty())
	{
		const auto at = what.find("Location:");
		if (at != std::string::npos)
			text = trimmed(what.substr(at + 9, what.find('\n', at) - at - 9));
	}
	return text.empty() ? trimmed(what) : text;
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
using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point t)
{
	return std::chrono::duration<double>(Clock::now() - t).count();
}
}  // namespace

/** What the sensor reports, shared by its successive driver threads (a
 * thread left behind keeps its reference: nothing it touches is freed). */
struct LiveSensor::Board
{
	mutable std::mutex mutex;
	Status status;
	Clock::time_point firstDelivery, lastDelivery, lastRestart;

	void delivered(Clock::time_point when)
	{
		std::lock_guard<std::mutex> lock(mutex);
		if (!status.delivered) firstDelivery = lastDelivery = when;
		const double gap = std::chrono::duration<double>(when - lastDelivery).count();
		if (gap > status.longestGap)
		{
			status.longestGap = gap;
			status.longestGapStart =
				std::chrono::duration<double>(lastDelivery - firstDelivery).count();
		}
		lastDelivery = when;
		status.received++;
		status.delivered = true;
	}
	void failed(const std::string& why)
	{
		std::lock_guard<std::mutex> lock(mutex);
		status.failures++;
		status.lastError = why;
		lastRestart = Clock::now();
	}
	/** [s] since the last observation or restart; 0 before the first one
	 * (the start has its own timeout). */
	double silentFor() const
	{
		std::lock_guard<std::mutex> lock(mutex);
		if (!status.delivered) return 0;
		return secondsSince(std::max(lastDelivery, lastRestart));
	}
};

/** One driver thread's state: everything it touches, owned with it. */
struct LiveSensor::Worker
{
	std::string section, driverName;
	size_t index = 0;
	double restartPause = 0, restartAfterSilence = 0;
	std::shared_ptr<mrpt::config::CConfigFileMemory> config;
	std::shared_ptr<Board> board;
	Sink sink;
	std::optional<RecordingReplayClock> replay;	 //!< a driver replaying a recording
	std::shared_ptr<mrpt::hwdrivers::CGenericSensor> driver;
	std::atomic<bool> stop{false}, done{false};
	/** steady-clock ticks when the current driver call began; 0: none. */
	std::atomic<Clock::rep> callSince{0};
	std::atomic<bool> inInitialize{false};
	std::mutex deliverMutex;  //!< held while delivering
	std::atomic<bool> abandoned{false};

	/** The thread is left behind: it can deliver and report nothing more.
	 * If it loops on send() to a dead device, it is freed to end. */
	void abandon()
	{
		stop = true;
		abandoned = true;
		std::lock_guard<std::mutex> lock(deliverMutex);	 // no delivery in flight
		DeadConnectionRescue::rescueAll();
	}

	std::shared_ptr<mrpt::hwdrivers::CGenericSensor> makeDriver(
		const mrpt::config::CConfigFileBase& cfg) const
	{
		return makeSensorDriver(driverName, section, board, cfg);
	}

	/** Runs f as a driver call: stuckFor() sees how long it lasts. */
	template <typename F>
	void call(F&& f)
	{
		callSince = Clock::now().time_since_epoch().count();
		try
		{
			f();
		}
		catch (...)
		{
			callSince = 0;
			throw;
		}
		callSince = 0;
	}

	/** A replayed recording's frame waits until it is due (false: skipped,
	 * or stopped while waiting); its stamp becomes the clock's. */
	bool replayWhenDue(mrpt::obs::CObservation& obs)
	{
		const auto due =
			replay->schedule(mrpt::Clock::toDouble(obs.timestamp), mrpt::Clock::nowDouble());
		if (!due)
		{
			std::lock_guard<std::mutex> lock(board->mutex);
			board->status.skipped++;
			return false;
		}
		const auto until = Clock::now() + std::chrono::duration_cast<Clock::duration>(
											   std::chrono::duration<double>(due->wait));
		while (!stop && Clock::now() < until)
			std::this_thread::sleep_until(
				std::min(until, Clock::now() + std::chrono::milliseconds(20)));
		obs.timestamp = mrpt::Clock::fromDouble(due->stamp);
		return !stop;
	}

	bool deliver(const std::shared_ptr<mrpt::obs::CObservation>& obs)
	{
		if (replay && !replayWhenDue(*obs)) return true;
		std::lock_guard<std::mutex> lock(deliverMutex);
		if (abandoned) return false;
		const auto now = Clock::now();
		DriverQuirks::correct(driverName, *obs);
		sink({index, obs, now});
		board->delivered(now);
		return true;
	}

	void run()
	{
		bool initialized = false;
		while (!stop)
		{
			try
			{
				if (!driver) driver = makeDriver(*config);
				if (!initialized)
				{
					inInitialize = true;
					call([&] { driver->initialize(); });
					inInitialize = false;
					initialized = true;
				}
				call([&] { driver->doProcess(); });
				const auto objects = driver->getObservations();
				for (const auto& [t, object] : objects)
					if (auto obs = std::dynamic_pointer_cast<mrpt::obs::CObservation>(object))
						if (!deliver(obs)) return;	// left behind
				if (objects.empty())
				{
					std::this_thread::sleep_for(std::chrono::milliseconds(1));
					if (restartAfterSilence > 0 && board->silentFor() > restartAfterSilence)
					{
						char why[96];
						std::snprintf(why, sizeof(why),
							"no observation for %.1f s without an error ([Live] "
							"restart_after_silence)",
							restartAfterSilence);
						throw std::runtime_error(why);
					}
				}
			}
			catch (const mrpt::serialization::CExceptionEOF&)
			{
				if (!replay) throw;	// not expected from a device: as any error
				// The recording is over: nothing more will come; no restart.
				std::lock_guard<std::mutex> lock(board->mutex);
				board->status.ended = "end of the recording";
				break;
			}
			catch (const std::exception& e)
			{
				inInitialize = false;
				if (abandoned) break;
				board->failed(driverMessage(e));
				call([&] { driver.reset(); });	// may block in the driver too
				initialized = false;
				const auto until = Clock::now() +
					std::chrono::duration_cast<Clock::duration>(
						std::chrono::duration<double>(restartPause));
				while (!stop && Clock::now() < until)
					std::this_thread::sleep_for(std::chrono::milliseconds(10));
			}
		}
		// The driver's destructor switches the device off.
		call([&] { driver.reset(); });
	}
};

/** `driver` of `[section]`, its keys loaded from cfg, its ERROR log
 * messages counted on `board`. */
std::shared_ptr<mrpt::hwdrivers::CGenericSensor> LiveSensor::makeSensorDriver(
	const std::string& driverName, const std::string& section,
	const std::shared_ptr<Board>& board, const mrpt::config::CConfigFileBase& cfg)
{
	auto d = mrpt::hwdrivers::CGenericSensor::createSensorPtr(driverName);
	if (!d)
		throw ConfigError("[" + section + "] driver = " + driverName +
			": not an MRPT sensor driver (e.g. CHokuyoURG, CLMS100Eth, CSickLaserSerial, "
			"CCameraSensor, or featloc's TcpOdometrySensor; names are case-sensitive)");
	// Drivers that log (C2DRangeFinderAbstract and others) report what
	// they could not read and retry; count it, so the run's report says so.
	if (auto* logger = dynamic_cast<mrpt::system::COutputLogger*>(d.get()))
		logger->logRegisterCallback(
			[b = board](std::string_view msg, mrpt::system::VerbosityLevel level,
				std::string_view, mrpt::Clock::time_point) {
				if (level < mrpt::system::LVL_ERROR) return;
				std::string text(msg);
				while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back())))
					text.pop_back();
				std::lock_guard<std::mutex> lock(b->mutex);
				b->status.driverErrors++;
				b->status.lastDriverError = text;
			});
	d->loadConfig(cfg, section);
	// CLMS100Eth (2.5.8) logs at DEBUG from its constructor: a console
	// line per scan. Information and above, as the other drivers.
	if (auto* logger = dynamic_cast<mrpt::system::COutputLogger*>(d.get()))
		if (logger->getMinLoggingLevel() < mrpt::system::LVL_INFO)
			logger->setMinLoggingLevel(mrpt::system::LVL_INFO);
	return d;
}

LiveSensor::LiveSensor(const TrackedConfig& cfg, std::string section, size_t index,
	const LiveOptions& options, Sink sink)
	: m_section(std::move(section)),
	  m_index(index),
	  m_restartPause(options.restart_pause),
	  m_restartAfterSilence(options.restart_after_silence),
	  m_sink(std::move(sink)),
	  m_config(std::make_shared<mrpt::config::CConfigFileMemory>(cfg.content())),
	  m_board(std::make_shared<Board>())
{
	m_driverName = cfg.read_string(m_section, "driver", "");
	const std::string where = cfg.sourceName() + ": [" + m_section + "]";
	if (m_driverName.empty())
		throw ConfigError(where + ": no 'driver' key (e.g. driver = CHokuyoURG)");
	m_address = addressKeys(*m_config, m_section);
	if (DriverQuirks::replaysRecording(m_driverName, cfg, m_section))
		m_replay = options.replay_clock == "recorded" ? RecordingReplayClock::Mode::Recorded
													   : RecordingReplayClock::Mode::Now;
	try
	{
		// Through the tracked config: the keys the driver reads are known.
		m_firstDriver = makeSensorDriver(m_driverName, m_section, m_board, cfg);
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

LiveSensor::~LiveSensor() { stop(0); }

void LiveSensor::launch(std::shared_ptr<mrpt::hwdrivers::CGenericSensor> driver)
{
	auto w = std::make_shared<Worker>();
	w->section = m_section;
	w->driverName = m_driverName;
	w->index = m_index;
	w->restartPause = m_restartPause;
	w->restartAfterSilence = m_restartAfterSilence;
	w->config = m_config;
	w->board = m_board;
	w->sink = m_sink;
	w->driver = std::move(driver);
	if (m_replay) w->replay.emplace(*m_replay);
	m_worker = w;
	m_thread = std::thread([w] {
		w->run();
		w->done = true;
	});
}

void LiveSensor::start()
{
	m_startedAt = Clock::now();
	launch(std::move(m_firstDriver));
}

bool LiveSensor::stop(double timeout)
{
	if (!m_worker) return true;
	m_worker->stop = true;
	const auto until = Clock::now() +
		std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(timeout));
	while (!m_worker->done && Clock::now() < until)
	{
		std::this_thread::sleep_for(std::chrono::milliseconds(5));
		rescueIfStuck();
	}
	if (!m_worker->done)
	{
		leaveBehind();	// still inside the driver
		return false;
	}
	m_thread.join();
	m_worker.reset();
	return true;
}

void LiveSensor::rescueIfStuck()
{
	// A call this long may be a write looping on a reset connection: free
	// it (DeadConnectionRescue touches dead connections only), so the
	// driver sees the closed link and recovers without being left behind.
	constexpr double kRescueAfter = 0.5;  // [s] MRPT's TCP reads time out in 0.1 s
	if (stuckFor() > kRescueAfter && secondsSince(m_lastRescue) > kRescueAfter)
	{
		DeadConnectionRescue::rescueAll();
		m_lastRescue = Clock::now();
	}
}

void LiveSensor::leaveBehind()
{
	m_worker->abandon();  // it can deliver nothing more
	m_thread.detach();
	m_worker.reset();
	std::lock_guard<std::mutex> lock(m_board->mutex);
	m_board->status.stuckDrivers++;
}

double LiveSensor::stuckFor() const
{
	if (!m_worker) return 0;
	const Clock::rep since = m_worker->callSince;
	if (since == 0) return 0;
	return secondsSince(Clock::time_point(Clock::duration(since)));
}

bool LiveSensor::initializing() const { return m_worker && m_worker->inInitialize; }

void LiveSensor::replaceStuckDriver(const std::string& why)
{
	if (!m_worker) return;
	leaveBehind();
	m_board->failed(why);
	launch(nullptr);  // a new driver, made and initialised by its thread
}

LiveSensor::Status LiveSensor::status() const
{
	std::lock_guard<std::mutex> lock(m_board->mutex);
	return m_board->status;
}
}  // namespace featloc
