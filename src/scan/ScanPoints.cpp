#include "featloc/scan/ScanPoints.h"

#include <mrpt/maps/CPointsMap.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace featloc
{
namespace
{
/** A valid beam's range is a return: finite, positive, below maxRange. */
bool isReturnRange(double r, const mrpt::obs::CObservation2DRangeScan& scan)
{
	return std::isfinite(r) && r > 0 && r < scan.maxRange;
}

/** The cos and sin of a scan's beam bearings, kept for the next scan with
 * the same bearings (every scan of one sensor): a sin and a cos per beam
 * were a tenth of a 361-beam PCM match. MRPT's
 * CSinCosLookUpTableFor2DScans keeps floats, with which a point's x, y
 * would disagree with its range by up to 1e-7 of it; the code relies on
 * x, y = r (cos, sin) of its bearing (RangeLattice::dequantize) and on
 * the same points bit for bit as before. */
struct BeamDirections
{
	std::vector<float> bearings;
	std::vector<double> cos, sin;

	/** MRPT's getScanAngle() is a function of the beam count, the
	 * aperture and the sweep direction alone: those are the key. */
	void update(const mrpt::obs::CObservation2DRangeScan& scan)
	{
		const size_t n = scan.getScanSize();
		if (n == bearings.size() && scan.aperture == m_aperture &&
			scan.rightToLeft == m_rightToLeft)
			return;
		m_aperture = scan.aperture;
		m_rightToLeft = scan.rightToLeft;
		bearings.resize(n);
		cos.resize(n);
		sin.resize(n);
		for (size_t i = 0; i < n; i++)
		{
			bearings[i] = scan.getScanAngle(i);
			cos[i] = std::cos(static_cast<double>(bearings[i]));
			sin[i] = std::sin(static_cast<double>(bearings[i]));
		}
	}

   private:
	float m_aperture = 0;
	bool m_rightToLeft = true;
};
}  // namespace

ScanPoints ScanPoints::fromScan(const mrpt::obs::CObservation2DRangeScan& scan)
{
	ScanPoints out;
	const size_t n = scan.getScanSize();
	out.maxRange = scan.maxRange;
	out.angularStep = n > 1 ? scan.aperture / static_cast<double>(n - 1) : 0;
	if (n < 2) return out;	// no bearing is defined for a single beam
	out.points.reserve(n);
	thread_local BeamDirections directions;
	directions.update(scan);
	for (size_t i = 0; i < n; i++)
	{
		// hasReturn(), reading the range once.
		if (!scan.getScanRangeValidity(i)) continue;
		const double r = scan.getScanRange(i);
		if (!isReturnRange(r, scan)) continue;
		ScanPoint p;
		p.range = r;
		p.bearing = directions.bearings[i];
		p.x = r * directions.cos[i];
		p.y = r * directions.sin[i];
		p.beam = static_cast<uint32_t>(i);
		out.points.push_back(p);
	}
	// Scanners sweeping clockwise (rightToLeft = false) list beams by
	// decreasing bearing: keep the counter-clockwise order everywhere.
	if (!scan.rightToLeft) std::reverse(out.points.begin(), out.points.end());
	return out;
}

bool ScanPoints::hasReturn(const mrpt::obs::CObservation2DRangeScan& scan, size_t i)
{
	return scan.getScanRangeValidity(i) && isReturnRange(scan.getScanRange(i), scan);
}

bool ScanPoints::samePointsAs(const ScanPoints& o) const
{
	if (points.size() != o.points.size() || angularStep != o.angularStep ||
		maxRange != o.maxRange)
		return false;
	return std::equal(points.begin(), points.end(), o.points.begin(),
		[](const ScanPoint& a, const ScanPoint& b) {
			return a.x == b.x && a.y == b.y && a.range == b.range && a.bearing == b.bearing &&
				a.beam == b.beam;
		});
}

ScanPoints ScanPoints::fromPointsMap(const mrpt::maps::CPointsMap& map)
{
	ScanPoints out;
	const size_t n = map.size();
	out.points.reserve(n);
	for (size_t i = 0; i < n; i++)
	{
		float x = 0, y = 0;
		map.getPoint(i, x, y);
		ScanPoint p;
		p.x = x;
		p.y = y;
		p.range = std::hypot(p.x, p.y);
		if (!(p.range > 0) || !std::isfinite(p.range)) continue;
		p.bearing = std::atan2(p.y, p.x);
		p.beam = static_cast<uint32_t>(i);
		out.points.push_back(p);
	}
	std::stable_sort(
		out.points.begin(), out.points.end(),
		[](const ScanPoint& a, const ScanPoint& b) {
			return a.bearing < b.bearing;
		});
	return out;
}

}  // namespace featloc
