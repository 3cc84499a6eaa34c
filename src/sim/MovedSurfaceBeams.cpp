#include "featloc/sim/MovedSurfaceBeams.h"

#include <algorithm>
#include <cmath>

namespace featloc
{
std::vector<uint32_t> MovedSurfaceBeams::of(const SimWorld& world, double t,
	const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::poses::CPose2D& robot,
	double earlier, double tolerance)
{
	std::vector<uint32_t> out;
	const size_t n = scan.getScanSize();
	if (n < 2) return out;
	const mrpt::poses::CPose2D sensor = robot + mrpt::poses::CPose2D(scan.sensorPose);
	const double first = -scan.aperture / 2.0;
	const double step = scan.aperture / static_cast<double>(n - 1);
	std::vector<double> ranges;
	world.castScan(t, sensor, scan, ranges);
	// Where each valid beam hits now, and how far that is from what was there.
	std::vector<mrpt::math::TPoint2D> hitPoints;
	std::vector<uint32_t> beams;
	for (size_t k = 0; k < n; k++)
	{
		const size_t i = scan.rightToLeft ? k : n - 1 - k;
		if (!scan.getScanRangeValidity(i) || !std::isfinite(ranges[k])) continue;
		const double a = sensor.phi() + first + step * static_cast<double>(k);
		hitPoints.emplace_back(sensor.x() + ranges[k] * std::cos(a), sensor.y() + ranges[k] * std::sin(a));
		beams.push_back(static_cast<uint32_t>(i));
	}
	const std::vector<double> d = world.distancesToSurfaces(hitPoints, earlier);
	for (size_t j = 0; j < d.size(); j++)
		if (d[j] > tolerance) out.push_back(beams[j]);
	std::sort(out.begin(), out.end());
	return out;
}
}  // namespace featloc
