#include "featloc/matchers/ReferenceOverlap.h"

#include <opencv2/core.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

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
	// The current points at the pose, and their bearings from the
	// reference's origin by OpenCV's vectorised cv::phase (361 atan2 were
	// a third of this function). Its error, about 0.3 deg as documented,
	// widens each window by kPhaseError: the window still holds every
	// reference point within `distance`, and the distances decide.
	constexpr double kPhaseError = 0.01;  // [rad]
	thread_local std::vector<double> xs, ys, bearings;
	const size_t count = current.size();
	xs.resize(count);
	ys.resize(count);
	bearings.resize(count);
	// In blocks, so that a count stopped early (stopBelow) has not placed
	// the points it never looks at: the probes of slid poses
	// (ScanMatcher, coarse_confirm_probe) mostly stop within the first
	// blocks.
	constexpr size_t kBlock = 64;
	size_t near = 0, cursor = 0, seen = 0;
	for (size_t begin = 0; begin < count; begin += kBlock)
	{
		const size_t end = std::min(count, begin + kBlock);
		for (size_t i = begin; i < end; i++)
			pose.composePoint(current.points[i].x, current.points[i].y, xs[i], ys[i]);
		const int cols = static_cast<int>(end - begin);
		cv::Mat angles(1, cols, CV_64F, bearings.data() + begin);
		cv::phase(cv::Mat(1, cols, CV_64F, xs.data() + begin),
			cv::Mat(1, cols, CV_64F, ys.data() + begin), angles);
		for (size_t i = begin; i < end; i++)
		{
			if (static_cast<double>(seen++ - near) > maxMisses) return static_cast<double>(near) / n;
			const double x = xs[i], y = ys[i];
			const double rho = std::sqrt(x * x + y * y);
			if (rho <= 2 * distance)
			{
				near += anyWithin(reference, cursor, -M_PI, M_PI, x, y, d2);
				continue;
			}
			const double bearing = bearings[i] > M_PI ? bearings[i] - 2 * M_PI : bearings[i];
			// asin(s) <= s (1 + s^2 / 4) for s <= 1/2: a window at least as wide.
			const double s = distance / rho;
			const double half = s * (1 + 0.25 * s * s) + kPhaseError;
			bool found = anyWithin(reference, cursor, bearing - half, bearing + half, x, y, d2);
			// The window wraps past +-pi on a scan of more than half a turn.
			if (!found && bearing - half < -M_PI)
				found = anyWithin(reference, cursor, bearing - half + 2 * M_PI, M_PI, x, y, d2);
			if (!found && bearing + half > M_PI)
				found = anyWithin(reference, cursor, -M_PI, bearing + half - 2 * M_PI, x, y, d2);
			near += found;
		}
	}
	return static_cast<double>(near) / n;
}
}  // namespace featloc
