#pragma once
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <queue>
#include <string>
#include <vector>

#include "featloc/io/EntrySource.h"
#include "featloc/live/LiveOptions.h"
#include "featloc/live/LiveSensor.h"
#include "featloc/live/RawlogRecorder.h"

namespace featloc
{
class TrackedConfig;

/** Live MRPT drivers as the pipeline's source (featloc-live): one
 * LiveSensor thread per `[Live] sensors` section; their observations are
 * merged in time order and passed on one at a time, exactly like the
 * entries of a format-#2 rawlog.
 *
 * Time order: an observation is passed on once no other sensor can still
 * send an older one: it has delivered something later, or the wall clock
 * minus that sensor's largest delay so far (arrival - stamp, plus 3 ms)
 * has passed the observation's time; or after `[Live] max_wait`. One older than
 * what was already passed on is late: it does not reach the pipeline (it
 * would go back in time) and is recorded in the late rawlog.
 *
 * Recording: every observation passed on is appended to the recording
 * (live.rawlog) at that moment, in that order, so replaying the recording
 * with featloc-run feeds the pipeline the same entries; nothing received is
 * dropped: when the stop flag rises or the duration is reached, the
 * drivers are stopped first and everything they delivered is passed on
 * before next() returns false. */
class LiveSource : public EntrySource
{
   public:
	struct SensorReport
	{
		std::string section, driver;
		LiveSensor::Status status;	//!< what the driver delivered, its restarts, gaps
		size_t passedOn = 0, late = 0;
		double rate = 0;  //!< [Hz] over the run
	};

	/** Makes the drivers (ConfigError for a bad sensor section) and opens
	 * the recordings; `duration` [s] from the first observation (0: until
	 * `stop`). Nothing runs until start(). */
	LiveSource(const TrackedConfig& cfg, const LiveOptions& options, std::string recordingPath,
		std::string lateRecordingPath, double duration, const std::atomic<bool>* stop);
	~LiveSource() override;

	/** Starts every driver and waits until each has delivered an
	 * observation. Throws InputError naming the section, driver, address
	 * and the driver's last error for one silent after
	 * `[Live] startup_timeout`. Returns early when `stop` rises. */
	void start();

	bool next(RawlogEntry& entry) override;
	double progress() const override;
	std::string name() const override { return m_recording.path(); }
	std::string description() const override;

	/** Where to say that a sensor fell silent (nothing for kSilence) and
	 * when it delivers again; called on the thread calling next(). */
	void setNotice(std::function<void(const std::string&)> notice) { m_notice = std::move(notice); }
	static constexpr double kSilence = 1.0;	 //!< [s]

	std::vector<SensorReport> report() const;
	/** "Ctrl-C / SIGTERM", "--duration reached", or "" while running. */
	std::string stopReason() const;
	size_t lateObservations() const;
	/** When the observation passed on as `observation` arrived from its
	 * driver (for the latency of a pose); nullopt when unknown. */
	std::optional<std::chrono::steady_clock::time_point> arrivalOf(const void* observation) const;
	/** When start() returned: every sensor had delivered. What arrived
	 * before waited for the slowest device's first observation. */
	std::optional<std::chrono::steady_clock::time_point> runningSince() const;
	/** Seconds since the first observation. */
	double secondsRunning() const;

   private:
	struct Pending
	{
		LiveSensor::Arrival arrival;
		double t = 0;  //!< [s] observation time
		size_t order = 0;  //!< arrival order, ties keep it
		bool operator>(const Pending& o) const
		{
			return t != o.t ? t > o.t : order > o.order;
		}
	};
	void onArrival(LiveSensor::Arrival a);
	/** 0 when p can be passed on now, else how long [s] until it can be
	 * unless another observation arrives first. */
	double waitBeforeRelease(const Pending& p, std::chrono::steady_clock::time_point now) const;
	bool stopping();
	void stopSensors();
	/** Every kSupervisionPeriod: frees or replaces drivers stuck in a call
	 * and notes restarts and sensors silent for kSilence. Then passes every
	 * pending notice to m_notice (outside the lock). */
	void supervise(std::chrono::steady_clock::time_point now);
	/** Leaves behind drivers stuck in a call and starts new ones. */
	void replaceStuckDrivers();
	void noteRestartsAndSilences(std::chrono::steady_clock::time_point now);	 //!< under m_mutex
	static std::string stuckNotice(const LiveSensor& s, double seconds, const std::string& when);

	LiveOptions m_options;
	double m_duration;
	const std::atomic<bool>* m_stop;
	RawlogRecorder m_recording;
	RawlogRecorder m_late;	//!< live-late.rawlog (empty when nothing was late)
	std::vector<std::unique_ptr<LiveSensor>> m_sensors;

	mutable std::mutex m_mutex;	 //!< guards everything below
	std::condition_variable m_arrived;
	std::priority_queue<Pending, std::vector<Pending>, std::greater<Pending>> m_pending;
	std::vector<std::optional<double>> m_latest;  //!< per sensor, newest time
	std::vector<std::optional<double>> m_maxDelay;	//!< per sensor, [s] arrival - stamp
	std::vector<size_t> m_passedOn, m_lateCount;
	size_t m_arrivals = 0, m_released = 0;
	std::optional<double> m_lastReleased;
	std::optional<std::chrono::steady_clock::time_point> m_firstArrival, m_runningSince;
	std::string m_stopReason;
	bool m_sensorsStopped = false;
	std::deque<std::pair<const void*, std::chrono::steady_clock::time_point>> m_recentArrivals;
	std::vector<std::optional<std::chrono::steady_clock::time_point>> m_lastArrival;
	std::vector<bool> m_silent;
	std::vector<size_t> m_restartsNoticed;
	std::vector<std::string> m_lastNoticedError;
	std::vector<std::string> m_notices;	 //!< not yet given
	std::function<void(const std::string&)> m_notice;
	std::chrono::steady_clock::time_point m_lastSupervision;
};
}  // namespace featloc
