#include "featloc/odometry/OdometryTimeline.h"

#include <mrpt/math/wrap2pi.h>

#include <algorithm>
#include <cmath>

namespace featloc
{
namespace
{
double seconds(mrpt::Clock::time_point a, mrpt::Clock::time_point b)
{
	return std::chrono::duration<double>(b - a).count();
}
}  // namespace

void OdometryTimeline::add(
	mrpt::Clock::time_point t, const mrpt::poses::CPose2D& odometry)
{
	m_readings.emplace_back(t, odometry);
}

bool OdometryTimeline::covers(mrpt::Clock::time_point t) const
{
	return !m_readings.empty() && m_readings.back().first >= t;
}

std::optional<mrpt::poses::CPose2D> OdometryTimeline::poseAt(
	mrpt::Clock::time_point t, double maxGap) const
{
	if (m_readings.empty()) return std::nullopt;
	// First reading at or after t.
	const auto after = std::lower_bound(
		m_readings.begin(), m_readings.end(), t,
		[](const auto& r, mrpt::Clock::time_point tt) { return r.first < tt; });
	if (after != m_readings.end() && after->first == t) return after->second;

	const bool hasAfter = after != m_readings.end();
	const bool hasBefore = after != m_readings.begin();
	if (hasBefore && hasAfter)
	{
		const auto& a = *std::prev(after);
		const auto& b = *after;
		const double span = seconds(a.first, b.first);
		if (span <= maxGap && span > 0)
		{
			// a (+) s * (b (-) a): constant velocity between the readings.
			const double s = seconds(a.first, t) / span;
			const mrpt::poses::CPose2D d = b.second - a.second;
			return a.second +
				mrpt::poses::CPose2D(
					   s * d.x(), s * d.y(), s * mrpt::math::wrapToPi(d.phi()));
		}
	}
	std::optional<mrpt::poses::CPose2D> best;
	double bestDt = maxGap;
	if (hasBefore)
	{
		const double dt = seconds(std::prev(after)->first, t);
		if (dt <= bestDt)
		{
			bestDt = dt;
			best = std::prev(after)->second;
		}
	}
	if (hasAfter)
	{
		const double dt = seconds(t, after->first);
		if (dt <= bestDt) best = after->second;
	}
	return best;
}

void OdometryTimeline::forgetBefore(mrpt::Clock::time_point t)
{
	while (m_readings.size() > 1 && m_readings[1].first <= t)
		m_readings.pop_front();
}
}  // namespace featloc
