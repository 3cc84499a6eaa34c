#include "featloc/gui/RunResults.h"

#include <algorithm>
#include <cmath>

namespace featloc
{
size_t RunResults::stepNearest(double t) const
{
	const auto it = std::lower_bound(
		steps.begin(), steps.end(), t, [](const Step& s, double v) { return s.t < v; });
	if (it == steps.end()) return steps.size() - 1;
	const size_t i = static_cast<size_t>(it - steps.begin());
	if (i > 0 && std::abs(steps[i - 1].t - t) <= std::abs(it->t - t)) return i - 1;
	return i;
}

std::optional<size_t> RunResults::stepAt(double t) const
{
	constexpr double kSameTime = 1e-6;	// [s]
	if (steps.empty()) return std::nullopt;
	const size_t i = stepNearest(t);
	if (std::abs(steps[i].t - t) > kSameTime) return std::nullopt;
	return i;
}

const RunResults::StereoFrame* RunResults::stereoAt(size_t step) const
{
	const auto it = std::lower_bound(stereo.begin(), stereo.end(), step,
		[](const StereoFrame& f, size_t s) { return f.step < s; });
	return it != stereo.end() && it->step == step ? &*it : nullptr;
}
}  // namespace featloc
