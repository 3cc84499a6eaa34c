#include "featloc/live/LiveSource.h"

#include <mrpt/core/Clock.h>
#include <mrpt/obs/CObservation.h>

#include <algorithm>
#include <thread>

#include "featloc/config/TrackedConfig.h"
#include "featloc/core/InputError.h"

namespace featloc
{
namespace
{
using Clock = std::chrono::steady_clock;

double secondsBetween(Clock::time_point a, Clock::time_point b)
{
	return std::chrono::duration<double>(b - a).count();
}

constexpr size_t kRecentArrivals = 4096;
// [s] added to a sensor's largest delay seen (scheduling jitter).
constexpr double kDelayMargin = 0.003;
// [s] how often next() looks at the drivers (stuck calls, restarts,
// silences): often enough for notices, not on every entry.
constexpr double kSupervisionPeriod = 0.02;
}  // namespace

LiveSource::LiveSource(const TrackedConfig& cfg, const LiveOptions& options,
	std::string recordingPath, std::string lateRecordingPath, double duration,
	const std::atomic<bool>* stop)
	: m_options(options),
	  m_duration(duration),
	  m_stop(stop),
	  m_recording(std::move(recordingPath)),
	  m_late(std::move(lateRecordingPath))
{
	for (size_t i = 0; i < m_options.sensors.size(); i++)
		m_sensors.push_back(std::make_unique<LiveSensor>(cfg, m_options.sensors[i], i, m_options,
			[this](LiveSensor::Arrival a) { onArrival(std::move(a)); }));
	m_latest.resize(m_sensors.size());
	m_maxDelay.resize(m_sensors.size());
	m_passedOn.assign(m_sensors.size(), 0);
	m_lateCount.assign(m_sensors.size(), 0);
	m_lastArrival.resize(m_sensors.size());
	m_silent.assign(m_sensors.size(), false);
	m_restartsNoticed.assign(m_sensors.size(), 0);
	m_lastNoticedError.resize(m_sensors.size());
}

LiveSource::~LiveSource() { stopSensors(); }

void LiveSource::onArrival(LiveSensor::Arrival a)
{
	const double t = mrpt::Clock::toDouble(a.observation->timestamp);
	const double delay = mrpt::Clock::toDouble(mrpt::Clock::now()) - t;
	{
		std::lock_guard<std::mutex> lock(m_mutex);
		if (!m_firstArrival) m_firstArrival = a.arrival;
		if (m_silent[a.sensor] && m_lastArrival[a.sensor])
		{
			char text[64];
			std::snprintf(text, sizeof(text), ": observations again after %.1f s",
				secondsBetween(*m_lastArrival[a.sensor], a.arrival));
			m_notices.push_back(m_sensors[a.sensor]->label() + text);
		}
		m_silent[a.sensor] = false;
		m_lastArrival[a.sensor] = a.arrival;
		auto& latest = m_latest[a.sensor];
		if (!latest || t > *latest) latest = t;
		auto& maxDelay = m_maxDelay[a.sensor];
		if (!maxDelay || delay > *maxDelay) maxDelay = delay;
		m_pending.push(Pending{std::move(a), t, m_arrivals++});
	}
	m_arrived.notify_one();
}

void LiveSource::start()
{
	for (auto& s : m_sensors) s->start();
	// Every device must answer: a silent one is an error, in bounded time.
	for (;;)
	{
		if (m_stop && m_stop->load()) return;
		bool all = true;
		for (const auto& s : m_sensors)
		{
			const auto st = s->status();
			if (st.delivered) continue;
			all = false;
			if (secondsBetween(s->startedAt(), Clock::now()) > m_options.startup_timeout)
				throw InputError("[" + s->section() + "] driver " + s->driver() + " (" +
					s->address() + "): no observation within " +
					std::to_string(static_cast<int>(m_options.startup_timeout)) +
					" s of its start ([Live] startup_timeout)" +
					(!st.lastError.empty()			 ? "; the driver said: " + st.lastError
							: !st.lastDriverError.empty() ? "; the driver logged: " + st.lastDriverError
														  : ": the device does not answer"));
		}
		if (all)
		{
			std::lock_guard<std::mutex> lock(m_mutex);
			m_runningSince = Clock::now();
			return;
		}
		std::this_thread::sleep_for(std::chrono::milliseconds(10));
	}
}

void LiveSource::supervise(Clock::time_point now)
{
	std::vector<std::string> notices;
	const bool due = secondsBetween(m_lastSupervision, now) >= kSupervisionPeriod;
	if (due)
	{
		m_lastSupervision = now;
		replaceStuckDrivers();	// outside the lock: a stuck driver may be delivering
	}
	{
		std::lock_guard<std::mutex> lock(m_mutex);
		if (due) noteRestartsAndSilences(now);
		notices.swap(m_notices);
	}
	if (m_notice)
		for (const auto& n : notices) m_notice(n);
}

void LiveSource::noteRestartsAndSilences(Clock::time_point now)
{
	for (size_t i = 0; i < m_sensors.size(); i++)
	{
		// A restart for a reason not said yet (the same reason over and
		// over, e.g. a refused connection, is said once).
		const auto st = m_sensors[i]->status();
		if (st.failures > m_restartsNoticed[i] && st.lastError != m_lastNoticedError[i])
		{
			m_notices.push_back(m_sensors[i]->label() + ": driver restarted: " + st.lastError);
			m_lastNoticedError[i] = st.lastError;
		}
		m_restartsNoticed[i] = st.failures;
		if (!st.ended.empty())
		{
			// A replayed recording that ended is not a device falling silent.
			if (!m_silent[i])
				m_notices.push_back(m_sensors[i]->label() + ": " + st.ended + " (" +
					std::to_string(st.received) + " observations); nothing more from it");
			m_silent[i] = true;
			continue;
		}
		if (m_silent[i] || !m_lastArrival[i] || secondsBetween(*m_lastArrival[i], now) < kSilence)
			continue;
		m_silent[i] = true;
		const std::string why = !st.lastDriverError.empty() ? st.lastDriverError : st.lastError;
		m_notices.push_back(m_sensors[i]->label() + ": no observation for " +
			std::to_string(static_cast<int>(kSilence)) + " s" +
			(why.empty() ? "" : " (the driver last said: " + why + ")"));
	}
}

double LiveSource::waitBeforeRelease(const Pending& p, Clock::time_point now) const
{
	const double maxWaitLeft = m_options.max_wait - secondsBetween(p.arrival.arrival, now);
	if (maxWaitLeft <= 0) return 0;
	const double wallNow = mrpt::Clock::toDouble(mrpt::Clock::now());
	double wait = 0;
	for (size_t s = 0; s < m_latest.size(); s++)
	{
		if (s == p.arrival.sensor || (m_latest[s] && *m_latest[s] >= p.t)) continue;
		// Nothing sent later by s yet; but what s sends from now on is
		// stamped at least wallNow - its largest delay so far (arrival -
		// stamp), so once that passes p.t nothing older can come.
		if (!m_maxDelay[s]) return maxWaitLeft;	// s has sent nothing yet
		wait = std::max(wait, p.t + *m_maxDelay[s] + kDelayMargin - wallNow);
	}
	return std::min(wait, maxWaitLeft);
}

bool LiveSource::stopping()
{
	std::lock_guard<std::mutex> lock(m_mutex);
	if (m_stopReason.empty())
	{
		if (m_stop && m_stop->load())
			m_stopReason = "Ctrl-C / SIGTERM";
		else if (m_duration > 0 && m_firstArrival &&
			secondsBetween(*m_firstArrival, Clock::now()) >= m_duration)
			m_stopReason = "--duration reached";
	}
	return !m_stopReason.empty();
}

void LiveSource::stopSensors()
{
	for (auto& s : m_sensors)
		if (!s->stop(m_options.driver_stuck_timeout))
		{
			std::lock_guard<std::mutex> lock(m_mutex);
			m_notices.push_back(stuckNotice(*s, m_options.driver_stuck_timeout, " at stop"));
		}
	std::lock_guard<std::mutex> lock(m_mutex);
	m_sensorsStopped = true;
}

std::string LiveSource::stuckNotice(const LiveSensor& s, double seconds, const std::string& when)
{
	char text[160];
	std::snprintf(text, sizeof(text),
		": driver stuck inside a call for %.1f s%s: its thread is left behind "
		"([Live] driver_stuck_timeout)",
		seconds, when.c_str());
	return s.label() + text;
}

void LiveSource::replaceStuckDrivers()
{
	if (m_sensorsStopped) return;
	for (auto& s : m_sensors)
	{
		s->rescueIfStuck();
		const double limit =
			s->initializing() ? m_options.startup_timeout : m_options.driver_stuck_timeout;
		const double stuck = s->stuckFor();
		if (stuck < limit) continue;
		const std::string notice = stuckNotice(*s, stuck, "") + ", a new driver started";
		s->replaceStuckDriver("stuck inside a driver call for " +
			std::to_string(static_cast<int>(limit)) + " s ([Live] driver_stuck_timeout)");
		std::lock_guard<std::mutex> lock(m_mutex);
		m_notices.push_back(notice);
	}
}

bool LiveSource::next(RawlogEntry& entry)
{
	for (;;)
	{
		// Stop the drivers first (outside the lock: their last
		// observations still arrive), then pass on everything they sent.
		if (!m_sensorsStopped && stopping()) stopSensors();
		supervise(Clock::now());
		std::unique_lock<std::mutex> lock(m_mutex);
		if (m_pending.empty())
		{
			if (m_sensorsStopped) return false;
			m_arrived.wait_for(lock, std::chrono::milliseconds(5));
			continue;
		}
		const auto now = Clock::now();
		if (const double wait = m_sensorsStopped ? 0 : waitBeforeRelease(m_pending.top(), now);
			wait > 0)
		{
			// Until it can go, an arrival, or the next look at the drivers.
			m_arrived.wait_for(lock, std::chrono::duration<double>(
				std::min(wait, kSupervisionPeriod)));
			continue;
		}
		Pending p = m_pending.top();
		m_pending.pop();
		const size_t sensor = p.arrival.sensor;
		if (m_lastReleased && p.t < *m_lastReleased)
		{
			m_lateCount[sensor]++;
			lock.unlock();
			m_late.record(*p.arrival.observation);
			continue;
		}
		m_lastReleased = p.t;
		m_passedOn[sensor]++;
		m_recentArrivals.emplace_back(p.arrival.observation.get(), p.arrival.arrival);
		if (m_recentArrivals.size() > kRecentArrivals) m_recentArrivals.pop_front();
		entry.index = m_released++;
		lock.unlock();
		m_recording.record(*p.arrival.observation);
		entry.object = p.arrival.observation;
		return true;
	}
}

double LiveSource::secondsRunning() const
{
	std::lock_guard<std::mutex> lock(m_mutex);
	return m_firstArrival ? secondsBetween(*m_firstArrival, Clock::now()) : 0.0;
}

double LiveSource::progress() const
{
	if (m_duration <= 0) return 0;
	return std::min(0.999, secondsRunning() / m_duration);
}

std::string LiveSource::description() const
{
	std::string out = "live:";
	for (const auto& s : m_sensors) out += " [" + s->section() + "] " + s->driver();
	return out + "; recording " + m_recording.path();
}

std::vector<LiveSource::SensorReport> LiveSource::report() const
{
	const double secs = secondsRunning();
	std::vector<SensorReport> out;
	std::lock_guard<std::mutex> lock(m_mutex);
	for (size_t i = 0; i < m_sensors.size(); i++)
	{
		SensorReport r;
		r.section = m_sensors[i]->section();
		r.driver = m_sensors[i]->driver();
		r.status = m_sensors[i]->status();
		r.passedOn = m_passedOn[i];
		r.late = m_lateCount[i];
		r.rate = secs > 0 ? static_cast<double>(r.status.received) / secs : 0;
		out.push_back(r);
	}
	return out;
}

std::string LiveSource::stopReason() const
{
	std::lock_guard<std::mutex> lock(m_mutex);
	return m_stopReason;
}

size_t LiveSource::lateObservations() const
{
	std::lock_guard<std::mutex> lock(m_mutex);
	size_t n = 0;
	for (auto c : m_lateCount) n += c;
	return n;
}

std::optional<Clock::time_point> LiveSource::runningSince() const
{
	std::lock_guard<std::mutex> lock(m_mutex);
	return m_runningSince;
}

std::optional<Clock::time_point> LiveSource::arrivalOf(const void* observation) const
{
	std::lock_guard<std::mutex> lock(m_mutex);
	for (auto it = m_recentArrivals.rbegin(); it != m_recentArrivals.rend(); ++it)
		if (it->first == observation) return it->second;
	return std::nullopt;
}
}  // namespace featloc
