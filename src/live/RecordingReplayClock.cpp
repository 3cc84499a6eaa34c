#include "featloc/live/RecordingReplayClock.h"

#include <algorithm>

namespace featloc
{
std::optional<RecordingReplayClock::Due> RecordingReplayClock::schedule(
	double stamp, double wallNow)
{
	if (m_mode == Mode::Recorded)
	{
		if (wallNow - stamp > kSkipAfter) return std::nullopt;
		return Due{std::max(0.0, stamp - wallNow), stamp};
	}
	if (!m_offset) m_offset = wallNow - stamp;
	const double due = stamp + *m_offset;
	return Due{std::max(0.0, due - wallNow), due};
}
}  // namespace featloc
