#pragma once
#include <mrpt/obs/obs_frwds.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace mrpt::maps
{
class CPointsMap;
}

namespace featloc
{
/** One valid range reading, in the sensor frame. */
struct ScanPoint
{
	double x = 0, y = 0;  //!< Cartesian coordinates [m]
	double range = 0;  //!< distance to the sensor origin [m]
	double bearing = 0;	 //!< angle from the sensor's X axis [rad], in (-pi, pi]
	uint32_t beam = 0;	//!< index of the beam in the original scan
	/** Points whose range errors are one and the same share a group
	 * (0: none, the point's error is its own): a range lattice's run of
	 * readings kept on their level (RangeLattice::dequantize) is off its
	 * surface by one rounding error, whatever the number of beams. */
	uint32_t sharedErrorGroup = 0;
	/** [m] the standard deviation of that shared error. */
	float sharedRangeSigma = 0;
};

/** The valid points of a 2-D range scan, in the sensor frame, ordered by
 * bearing (counter-clockwise), which every featloc matcher relies on:
 * segmentation walks consecutive points, IDC's matching-range rule and
 * correspondence search use the angular order.
 *
 * Invalid readings are not stored: a beam marked invalid, or with a range
 * that is not finite, not positive, or at/above the sensor's maxRange (a
 * "no return"), is skipped. */
struct ScanPoints
{
	std::vector<ScanPoint> points;
	/** Nominal angle between consecutive beams of the source scan [rad]; 0
	 * when the points did not come from an evenly spaced scan. */
	double angularStep = 0;
	/** Maximum range of the sensor [m] (0 if unknown). */
	double maxRange = 0;

	size_t size() const { return points.size(); }
	bool empty() const { return points.empty(); }
	const ScanPoint& operator[](size_t i) const { return points[i]; }

	/** The same points (coordinates, ranges, bearings and beam indices
	 * bit for bit) and the same sensor figures. */
	bool samePointsAs(const ScanPoints& o) const;

	/** Valid readings of a scan (hasReturn()), in its sensor frame
	 * (sensorPose is NOT applied). A scan of fewer than two beams gives no
	 * points. */
	static ScanPoints fromScan(const mrpt::obs::CObservation2DRangeScan& scan);

	/** Whether beam i of `scan` returned from a surface: marked valid, and
	 * its range finite and inside (0, maxRange) (at maxRange nothing was in
	 * range). Every per-beam use of a scan (the matchers' points, the
	 * global search's hits, the map's seen-through beams) counts the same
	 * beams with it. */
	static bool hasReturn(const mrpt::obs::CObservation2DRangeScan& scan, size_t i);

	/** Points of a map (its own frame), sorted by bearing around its origin.
	 * Used by the MRPT alignment adapter. */
	static ScanPoints fromPointsMap(const mrpt::maps::CPointsMap& map);
};

}  // namespace featloc
