#include "featloc/sim/MovedSurfaceBeams.h"

#include <algorithm>
#include <cmath>

#include "featloc/sim/RayCaster.h"

namespace featloc
{
namespace
{
double pointSegmentDistance(const mrpt::math::TPoint2D& p, const WallSegment& s)
{
	const double ex = s.b.x - s.a.x, ey = s.b.y - s.a.y;
	const double len2 = ex * ex + ey * ey;
	const double u =
		len2 > 0 ? std::clamp(((p.x - s.a.x) * ex + (p.y - s.a.y) * ey) / len2, 0.0, 1.0) : 0.0;
	return std::hypot(p.x - (s.a.x + u * ex), p.y - (s.a.y + u * ey));
}
}  // namespace

std::vector<uint32_t> MovedSurfaceBeams::of(const SimWorld& world, double t,
	const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::poses::CPose2D& robot,
	double earlier, double tolerance)
{
	std::vector<uint32_t> out;
	const size_t n = scan.getScanSize();
	if (n < 2) return out;
	const mrpt::poses::CPose2D sensor = robot + mrpt::poses::CPose2D(scan.sensorPose);
	// The exact ranges, cast as the simulator casts them (RangeScanFisherInformation).
	const double first = -scan.aperture / 2.0;
	const double step = scan.aperture / static_cast<double>(n - 1);
	std::vector<CircleShape> circles, circlesThen;
	std::vector<WallSegment> scratch, scratchThen;
	world.circlesAt(t, circles);
	world.circlesAt(earlier, circlesThen);
	const auto& segments = world.segmentsAt(t, scratch);
	const auto& segmentsThen = world.segmentsAt(earlier, scratchThen);
	std::vector<double> ranges;
	RayCaster::cast(sensor.asTPose(), first, step, n, scan.maxRange, segments, circles, ranges);
	for (size_t k = 0; k < n; k++)
	{
		const size_t i = scan.rightToLeft ? k : n - 1 - k;
		if (!scan.getScanRangeValidity(i) || !std::isfinite(ranges[k])) continue;
		const double a = sensor.phi() + first + step * static_cast<double>(k);
		const mrpt::math::TPoint2D p(
			sensor.x() + ranges[k] * std::cos(a), sensor.y() + ranges[k] * std::sin(a));
		double nearest = INFINITY;
		for (const auto& s : segmentsThen) nearest = std::min(nearest, pointSegmentDistance(p, s));
		for (const auto& c : circlesThen)
			nearest = std::min(
				nearest, std::abs(std::hypot(p.x - c.centre.x, p.y - c.centre.y) - c.radius));
		if (nearest > tolerance) out.push_back(static_cast<uint32_t>(i));
	}
	std::sort(out.begin(), out.end());
	return out;
}
}  // namespace featloc
