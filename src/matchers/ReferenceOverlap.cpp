#include "featloc/matchers/ReferenceOverlap.h"

#include <cmath>

namespace featloc
{
namespace
{
/** Walks the reference points (sorted by bearing) from `cursor` to the
 * first with bearing >= from, then checks those up to `to` for one within
 * sqrt(d2) of (x, y). Consecutive current points have nearby bearings, so
 * the cursor moves a few steps each time instead of a binary search. */
bool anyWithin(const ScanPoints& reference, size_t& cursor, double from, double to, double x,
	double y, double d2)
{
	const auto& ref = reference.points;
	while (cursor > 0 && ref[cursor - 1].bearing >= from) cursor--;
	while (cursor < ref.size() && ref[cursor].bearing < from) cursor++;
	for (size_t i = cursor; i < ref.size() && ref[i].bearing <= to; i++)
		if ((ref[i].x - x) * (ref[i].x - x) + (ref[i].y - y) * (ref[i].y - y) <= d2) return true;
	return false;
}
}  // namespace

double ReferenceOverlap::share(const ScanPoints& reference, const ScanPoints& current,
	const mrpt::poses::CPose2D& pose, double distance, double stopBelow)
{
	if (current.empty() || reference.empty()) return 0;
	const double d2 = distance * distance;
	const double n = static_cast<double>(current.size());
	// More misses than this and the share is below stopBelow.
	const double maxMisses = (1 - stopBelow) * n;
	size_t near = 0, cursor = 0, seen = 0;
	for (const ScanPoint& p : current.points)
	{
		if (static_cast<double>(seen++ - near) > maxMisses) break;
		double x = 0, y = 0;
		pose.composePoint(p.x, p.y, x, y);
		const double rho = std::sqrt(x * x + y * y);
		if (rho <= 2 * distance)
		{
			near += anyWithin(reference, cursor, -M_PI, M_PI, x, y, d2);
			continue;
		}
		const double bearing = std::atan2(y, x);
		// asin(s) <= s (1 + s^2 / 4) for s <= 1/2: a window at least as wide.
		const double s = distance / rho;
		const double half = s * (1 + 0.25 * s * s);
		bool found = anyWithin(reference, cursor, bearing - half, bearing + half, x, y, d2);
		// The window wraps past +-pi on a scan of more than half a turn.
		if (!found && bearing - half < -M_PI)
			found = anyWithin(reference, cursor, bearing - half + 2 * M_PI, M_PI, x, y, d2);
		if (!found && bearing + half > M_PI)
			found = anyWithin(reference, cursor, -M_PI, bearing + half - 2 * M_PI, x, y, d2);
		near += found;
	}
	return static_cast<double>(near) / n;
}
}  // namespace featloc
