#pragma once
#include <mrpt/core/Clock.h>
#include <mrpt/poses/CPose2D.h>

#include <deque>
#include <optional>
#include <utility>

namespace featloc
{
/** Absolute odometry readings (CObservationOdometry, rawlog format #2) over
 * time, to know the odometry pose at a laser scan's time: readings rarely
 * share the scan's timestamp. */
class OdometryTimeline
{
   public:
	/** Appends a reading; times must increase (the caller checks). */
	void add(mrpt::Clock::time_point t, const mrpt::poses::CPose2D& odometry);

	bool empty() const { return m_readings.empty(); }
	/** True when a reading at or after `t` exists. */
	bool covers(mrpt::Clock::time_point t) const;
	/** Time of the newest reading (undefined when empty). */
	mrpt::Clock::time_point newest() const { return m_readings.back().first; }

	/** Odometry pose at `t`: interpolated on SE(2) between the readings
	 * around `t` when they are at most `maxGap` seconds apart, else the
	 * nearest reading within `maxGap` seconds, else nothing. */
	std::optional<mrpt::poses::CPose2D> poseAt(
		mrpt::Clock::time_point t, double maxGap) const;

	/** Odometry pose at `t`, after the newest reading by at most
	 * `maxAhead` seconds: the last two readings' motion continued at
	 * constant velocity (they must be at most `maxGap` apart), so a live
	 * step need not wait for the next reading. Nothing when `t` is not
	 * after the newest reading or is too far after it. */
	std::optional<mrpt::poses::CPose2D> extrapolatedAt(
		mrpt::Clock::time_point t, double maxGap, double maxAhead) const;

	/** Forgets readings no longer needed for times >= t (keeps the last two
	 * before t: extrapolatedAt needs them). */
	void forgetBefore(mrpt::Clock::time_point t);

   private:
	std::deque<std::pair<mrpt::Clock::time_point, mrpt::poses::CPose2D>>
		m_readings;
};
}  // namespace featloc
