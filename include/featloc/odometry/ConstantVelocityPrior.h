#pragma once
#include <mrpt/core/Clock.h>
#include <mrpt/poses/CPose2D.h>

#include <deque>
#include <optional>
#include <utility>

namespace featloc
{
/** The motion of a step without odometry ([Odometry] no_odometry_prior =
 * constant_velocity): the estimated poses of the last `window` seconds give
 * a velocity, continued over the step. Over a window rather than the last
 * step: at 40 Hz, 1 cm of pose noise between two steps is 0.4 m/s. */
class ConstantVelocityPrior
{
   public:
	explicit ConstantVelocityPrior(double window) : m_window(window) {}

	/** The estimate at t (times must increase; a repeated time is ignored). */
	void add(mrpt::Clock::time_point t, const mrpt::poses::CPose2D& pose);
	/** Forgets the poses (the estimate restarted: a relocalization). */
	void clear() { m_poses.clear(); }

	/** Robot-frame motion from the newest pose to t at the window's
	 * velocity; nothing until the poses span at least half the window. */
	std::optional<mrpt::poses::CPose2D> motionTo(mrpt::Clock::time_point t) const;

   private:
	double m_window;
	std::deque<std::pair<mrpt::Clock::time_point, mrpt::poses::CPose2D>> m_poses;
};
}  // namespace featloc
