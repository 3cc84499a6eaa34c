#pragma once
#include <mrpt/poses/CPose2D.h>

#include "featloc/scan/ScanPoints.h"

namespace featloc
{
/** The share of a current scan's points that a pose puts within a distance
 * of some reference point: how much of the scan the reference confirms at
 * that pose. ScanMatcher uses it to skip the correlative search when the
 * iterations from the guess already land on a pose the points confirm
 * (`coarse_confirm_share`).
 *
 * Exact, and without a k-d tree: a reference point within d of a point at
 * range rho from the reference sensor lies within asin(d / rho) of its
 * bearing, and the reference points are sorted by bearing
 * (ScanPoints), so each current point looks only at that bearing window,
 * and nothing is built per pair (MRPT's k-d tree, CSimplePointsMap, would
 * be built for every reference scan). ReferencePolyline::closestPoint uses
 * the same bound to search a reference polyline's edges; building one
 * (segments, local lines) per pair is what this avoids. */
class ReferenceOverlap
{
   public:
	/** `reference` and `current` in their sensor frames; `pose` is the
	 * current sensor's pose in the reference's. With stopBelow > 0 the
	 * count stops as soon as the share cannot reach it, and what is
	 * returned is then some value below stopBelow (a caller that only
	 * needs the answer to "at least stopBelow?" need not count every
	 * point). */
	static double share(const ScanPoints& reference, const ScanPoints& current,
		const mrpt::poses::CPose2D& pose, double distance, double stopBelow = 0);
};
}  // namespace featloc
