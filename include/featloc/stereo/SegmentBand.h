#pragma once
#include <algorithm>
#include <cmath>

#include "featloc/stereo/SegmentMatch.h"
#include "featloc/stereo/VerticalSegment.h"

namespace featloc
{
/** Calls f(u, v) for the left-image pixels a match covers: every second
 * row of its common rows, +-halfWidth px around the left segment, inside
 * a W x H image. */
template <typename F>
void forSegmentBand(const VerticalSegment& l, const SegmentMatch& m, int W, int H, int halfWidth, F&& f)
{
	for (int v = std::max(0, static_cast<int>(std::ceil(m.vLow))); v <= std::min(H - 1, static_cast<int>(m.vHigh)); v += 2)
	{
		const int u0 = static_cast<int>(std::lround(l.uAt(v)));
		for (int u = std::max(0, u0 - halfWidth); u <= std::min(W - 1, u0 + halfWidth); u++) f(u, v);
	}
}
}  // namespace featloc
