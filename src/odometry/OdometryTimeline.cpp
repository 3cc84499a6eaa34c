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

/** a (+) s * (b (-) a) with s = (t - t_a) / (t_b - t_a): constant velocity
 * through the readings a and b (s > 1 continues past b). */
mrpt::poses::CPose2D constantVelocity(
	const std::pair<mrpt::Clock::time_point, mrpt::poses::CPose2D>& a,
	const std::pair<mrpt::Clock::time_point, mrpt::poses::CPose2D>& b,
	mrpt::Clock::time_point t)
{
	const double s = seconds(a.first, t) / seconds(a.first, b.first);
	const mrpt::poses::CPose2D d = b.second - a.second;
	return a.second +
		mrpt::poses::CPose2D(s * d.x(), s * d.y(), s * mrpt::math::wrapToPi(d.phi()));
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
		if (span <= maxGap && span > 0) return constantVelocity(a, b, t);
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

std::optional<mrpt::poses::CPose2D> OdometryTimeline::extrapolatedAt(
	mrpt::Clock::time_point t, double maxGap, double maxAhead) const
{
	if (m_readings.size() < 2 || t <= m_readings.back().first) return std::nullopt;
	const auto& a = m_readings[m_readings.size() - 2];
	const auto& b = m_readings.back();
	const double span = seconds(a.first, b.first);
	if (span <= 0 || span > maxGap || seconds(b.first, t) > maxAhead) return std::nullopt;
	return constantVelocity(a, b, t);
}

void OdometryTimeline::forgetBefore(mrpt::Clock::time_point t)
{
	while (m_readings.size() > 2 && m_readings[2].first <= t)
		m_readings.pop_front();
}
}  // namespace featloc
