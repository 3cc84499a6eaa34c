#pragma once
#include <mrpt/math/TPose2D.h>

#include <cstddef>

#include "featloc/matchers/ReferencePolyline.h"
#include "featloc/scan/ScanPoints.h"
#include "featloc/scan/ScanSegment.h"

namespace featloc
{
/** Whether a segment of the current scan lies where the rest of the match
 * puts it: its points' signed point-to-line residuals at the estimate,
 * against the reference's local lines, fitted by an offset and a slope
 * along the segment (a thing that was pushed, a door that turned about
 * its hinge), and that fit's chi-square under the range noise. A static
 * segment's residuals are noise around zero; one that moved between the
 * scans by a few centimetres, less than any distance gate at the matcher's
 * pairing distance, leaves a fit of tens of sigmas. Only the points the
 * matcher pairs count (within maxDistance of a reference line). */
class SegmentResidualTest
{
   public:
	struct Result
	{
		size_t points = 0;	//!< residuals fitted
		double offset = 0;	//!< [m] mean residual (positive: nearer the sensor)
		double slope = 0;  //!< [m per m along the segment]
		double chi2 = 0;  //!< of the fit (2 dof), under sigma
	};

	static Result run(const ReferencePolyline& reference, const ScanPoints& current,
		const ScanSegment& segment, const mrpt::math::TPose2D& x, double sigma,
		double maxDistance);
};
}  // namespace featloc
