#include "featloc/sim/SwingingDoor.h"

#include <cmath>
#include <stdexcept>

namespace featloc
{
SwingingDoor::SwingingDoor(Params params) : m_params(std::move(params))
{
	if (m_params.swing.empty())
		throw std::invalid_argument("door '" + m_params.name + "' has no swing keyframe");
	for (size_t i = 1; i < m_params.swing.size(); i++)
		if (!(m_params.swing[i].first > m_params.swing[i - 1].first))
			throw std::invalid_argument(
				"door '" + m_params.name + "': swing times must increase");
	if (!(m_params.length > 0))
		throw std::invalid_argument("door '" + m_params.name + "': length must be > 0");
	if (m_params.period < 0 ||
		(m_params.period > 0 &&
			(m_params.swing.front().first < 0 || m_params.swing.back().first >= m_params.period)))
		throw std::invalid_argument(
			"door '" + m_params.name + "': swing times must lie in [0, period)");
}

double SwingingDoor::angleAt(double t) const
{
	const auto& k = m_params.swing;
	if (m_params.period > 0)
	{
		// One period: from the last keyframe back round to the first.
		t = std::fmod(t, m_params.period);
		if (t < 0) t += m_params.period;
		if (t >= k.back().first && k.size() > 1)
		{
			const double span = m_params.period - k.back().first + k.front().first;
			const double f = (t - k.back().first) / span;
			return k.back().second + f * (k.front().second - k.back().second);
		}
		if (t < k.front().first && k.size() > 1)
		{
			const double span = m_params.period - k.back().first + k.front().first;
			const double f = (t + m_params.period - k.back().first) / span;
			return k.back().second + f * (k.front().second - k.back().second);
		}
	}
	if (t <= k.front().first) return k.front().second;
	for (size_t i = 1; i < k.size(); i++)
		if (t < k[i].first)
		{
			const double f = (t - k[i - 1].first) / (k[i].first - k[i - 1].first);
			return k[i - 1].second + f * (k[i].second - k[i - 1].second);
		}
	return k.back().second;
}

WallSegment SwingingDoor::segmentAt(double t) const
{
	const double a = angleAt(t);
	WallSegment s;
	s.a = m_params.hinge;
	s.b = {m_params.hinge.x + m_params.length * std::cos(a),
		m_params.hinge.y + m_params.length * std::sin(a)};
	s.object = m_params.name;
	s.texture = "door";
	return s;
}
}  // namespace featloc
