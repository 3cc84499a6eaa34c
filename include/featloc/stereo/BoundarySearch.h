#pragma once
#include <string>
#include <vector>

#include "featloc/stereo/PlanarRegion.h"

namespace featloc
{
/** Where a reference plane ends in the left image (Moon, Miura & Shirai
 * 1999, section 3.2).
 *
 * The search region is the end's predicted 3-sigma window. In each row
 * where the plane fills the window's inner edge, the boundary pixel is
 * where the plane's pixels stop (the last plane pixel before a run of
 * min_gap non-plane pixels, outward). A virtual mean m is moved over the
 * window in 0.1 px steps and the variance of the boundary pixels about it
 * computed; the boundary is the m of minimum variance and its sigma the
 * square root of that variance (the rows' spread: an SAD boundary is
 * fattened by up to half the block, the same way in every row, so the
 * spread, not the spread / sqrt(rows), is its uncertainty), at least
 * sigma_img.
 *
 * The paper's rule: a boundary inward of the outermost segment on the
 * plane is moved to that segment. With snap_to_segment (featloc's
 * addition, on by default), an outermost segment within 3 sigma outward
 * of the disparity boundary is taken as the boundary too, with
 * sigma_img: the intensity edge of the plane's end is sharper than the
 * SAD disparity's. Without a disparity boundary in the window (the plane
 * continues, e.g. a whiteboard on a wall), the outermost segment in the
 * window is the boundary; without either, there is none. */
class BoundarySearch
{
   public:
	struct Options
	{
		double sigma_img = 0.5;	 //!< [px]
		double window_sigmas = 3;
		int min_gap = 3;  //!< [px] non-plane run that ends the plane in a row
		unsigned int min_rows = 10;
		bool snap_to_segment = true;
	};
	BoundarySearch() = default;
	explicit BoundarySearch(const Options& o) : options(o) {}
	Options options;

	struct Result
	{
		bool found = false;
		bool atA = true;  //!< at the region's end a (else b)
		double u = 0, sigma = 0;  //!< [px] left-image column and its sigma
		size_t rows = 0;  //!< rows with a disparity boundary
		std::string method;	 //!< "disparity", "outer segment", "disparity, snapped to segment"
	};

	/** The boundary at end a (atA) or b of `region`; `segmentColumns` are
	 * the left-image columns of the segments found on the plane. */
	Result search(const PlanarRegion& region, bool atA, const std::vector<double>& segmentColumns) const;
};
}  // namespace featloc
