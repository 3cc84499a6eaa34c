#include "featloc/sim/RangeScanFisherInformation.h"

#include <mrpt/poses/CPose3D.h>

#include <cmath>
#include <stdexcept>

#include "featloc/sim/RayCaster.h"

namespace featloc
{
RangeScanFisherInformation::Result RangeScanFisherInformation::of(const SimWorld& world,
	double t, const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::poses::CPose2D& robot)
{
	const double sigma = scan.stdError;
	if (!(sigma > 0))
		throw std::invalid_argument("the scan declares no range noise (stdError = " +
			std::to_string(sigma) + "): no Fisher information");
	const size_t n = scan.getScanSize();
	Result res;
	auto& info = res.information;
	info.setZero();
	if (n < 2) return res;

	const mrpt::poses::CPose2D mount(scan.sensorPose);
	const mrpt::poses::CPose2D sensor = robot + mount;
	// The exact ranges, and what each beam hit.
	const double first = -scan.aperture / 2.0;
	const double step = scan.aperture / static_cast<double>(n - 1);
	std::vector<double> ranges;
	std::vector<RayCaster::Hit> hits;
	world.castScan(t, sensor, scan, ranges, &hits);
	// Static shapes come first among the segments and among the circles
	// (SimWorld::segmentsAt, circlesAt).
	auto isStatic = [&](const RayCaster::Hit& h) {
		return h.index < (h.circle ? world.circles().size() : world.segments().size());
	};

	// d s / d theta: the mount's lever arm turned with the robot.
	const double c = std::cos(robot.phi()), s = std::sin(robot.phi());
	const double dsx = -s * mount.x() - c * mount.y(), dsy = c * mount.x() - s * mount.y();
	for (size_t k = 0; k < n; k++)
	{
		const size_t i = scan.rightToLeft ? k : n - 1 - k;	// the scan's index of beam k
		if (!scan.getScanRangeValidity(i)) continue;
		res.beamsValid++;
		if (!(std::abs(scan.getScanRange(i) - ranges[k]) <= 5 * sigma)) res.beamsOff++;
		if (!std::isfinite(ranges[k]) || !isStatic(hits[k])) continue;
		const double a = sensor.phi() + first + step * static_cast<double>(k);
		const double vx = std::cos(a), vy = std::sin(a);
		const double nx = std::cos(hits[k].normal), ny = std::sin(hits[k].normal);
		const double nv = nx * vx + ny * vy;
		if (std::abs(nv) < 1e-9) continue;	// grazing: the range is not defined to first order
		const double r = ranges[k];
		const double g[3] = {-nx / nv, -ny / nv, -(nx * dsx + ny * dsy + r * (-nx * vy + ny * vx)) / nv};
		for (int p = 0; p < 3; p++)
			for (int q = 0; q < 3; q++) info(p, q) += g[p] * g[q] / (sigma * sigma);
		res.beamsUsed++;
	}
	return res;
}
}  // namespace featloc
