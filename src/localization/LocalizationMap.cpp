#include "featloc/localization/LocalizationMap.h"

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "featloc/scan/ScanPoints.h"

namespace featloc
{
LocalizationMap::LocalizationMap(
	std::shared_ptr<const mrpt::maps::COccupancyGridMap2D> grid, std::string path, std::string kind,
	mrpt::math::TPoint2D gridOffset)
	: m_grid(std::move(grid)), m_path(std::move(path)), m_kind(std::move(kind)), m_gridOffset(gridOffset)
{
	const auto& g = *m_grid;
	for (unsigned int y = 0; y < g.getSizeY(); y++)
		for (unsigned int x = 0; x < g.getSizeX(); x++)
			if (1.0f - g.getCell(x, y) > kOccupiedThreshold)
				m_occupied.emplace_back(g.idx2x(x) - m_gridOffset.x, g.idx2y(y) - m_gridOffset.y);
}

mrpt::obs::CObservation2DRangeScan LocalizationMap::virtualScan(
	const mrpt::obs::CObservation2DRangeScan& like, const mrpt::poses::CPose2D& robotPose) const
{
	mrpt::obs::CObservation2DRangeScan v;
	v.aperture = like.aperture;
	v.rightToLeft = like.rightToLeft;
	v.maxRange = like.maxRange;
	v.sensorPose = like.sensorPose;
	v.stdError = like.stdError;
	v.timestamp = like.timestamp;
	v.sensorLabel = like.sensorLabel + "_map";
	if (like.getScanSize() < 2) return v;  // MRPT's simulator needs two beams
	const mrpt::poses::CPose2D inGrid(
		robotPose.x() + m_gridOffset.x, robotPose.y() + m_gridOffset.y, robotPose.phi());
	m_grid->laserScanSimulator(v, inGrid, kOccupiedThreshold, like.getScanSize());
	// The surface that made a cell occupied lies on average at its centre
	// (a scan's end point anywhere in it, a drawn wall through its middle),
	// half a cell past the edge where a beam enters it. MRPT 2.5.8's ray
	// marcher returns the first of its steps (RAYTRACE_STEP_SIZE_IN_CELL_UNITS
	// cells) inside the cell: on average half a step past the edge. The
	// difference is added (tests/LocalizationMapTest: no bias left).
	const double step = mrpt::maps::COccupancyGridMap2D::RAYTRACE_STEP_SIZE_IN_CELL_UNITS;
	const float extra = static_cast<float>((0.5 - 0.5 * step) * m_grid->getResolution());
	for (size_t i = 0; i < v.getScanSize(); i++)
		if (v.getScanRangeValidity(i)) v.setScanRange(i, v.getScanRange(i) + extra);
	return v;
}

double LocalizationMap::shareSeenThrough(
	const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::poses::CPose2D& robotPose) const
{
	return shareOf(beamsSeenThrough(scan, robotPose));
}

double LocalizationMap::shareOf(const std::vector<bool>& seenThrough)
{
	const auto n = std::count(seenThrough.begin(), seenThrough.end(), true);
	return seenThrough.empty() ? 0.0 : static_cast<double>(n) / static_cast<double>(seenThrough.size());
}

std::vector<bool> LocalizationMap::beamsSeenThrough(
	const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::poses::CPose2D& robotPose) const
{
	const auto expected = virtualScan(scan, robotPose);
	std::vector<bool> out;
	for (size_t i = 0; i < scan.getScanSize(); i++)
	{
		if (!ScanPoints::hasReturn(scan, i)) continue;
		const double r = scan.getScanRange(i);
		// A beam on which the map has nothing is not seen through.
		const double e = expected.getScanRangeValidity(i) ? expected.getScanRange(i) : HUGE_VAL;
		out.push_back(r > e + std::max(kSeeThroughMargin, kSeeThroughShare * e));
	}
	return out;
}

std::string LocalizationMap::describe() const
{
	char buf[160];
	std::snprintf(buf, sizeof(buf), " (%s, %u x %u cells of %.3f m)", m_kind.c_str(),
		m_grid->getSizeX(), m_grid->getSizeY(), m_grid->getResolution());
	return m_path + buf;
}
}  // namespace featloc
