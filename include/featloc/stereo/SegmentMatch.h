#pragma once
#include <cstddef>

namespace featloc
{
/** A left/right pair of vertical segments (indices into the two lists)
 * with Lee & Leou's similarity terms. */
struct SegmentMatch
{
	size_t left = 0, right = 0;
	double overlap = 0;	 //!< common rows / rows of either
	double orientation = 0;	 //!< 1 - |angle difference| / max_angle_diff
	double lengthSimilarity = 0;  //!< eq. (18): min length / max length
	double similarity = 0;	//!< weighted sum of the three
	double disparity = 0;  //!< [px] u_left - u_right at the middle of the common rows
	double vLow = 0, vHigh = 0;	 //!< [px] common rows
};
}  // namespace featloc
