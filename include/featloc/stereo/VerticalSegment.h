#pragma once
#include <cstddef>

namespace featloc
{
/** A near-vertical line segment in one image (Moon, Miura & Shirai 1999,
 * section 2.1): a chain of horizontal-derivative maxima of one polarity,
 * with the column fitted by least squares along its rows. Pixel centres
 * are at integer coordinates. */
struct VerticalSegment
{
	double u = 0;  //!< [px] column at vMid()
	double slope = 0;  //!< du/dv
	double vTop = 0, vBottom = 0;  //!< [px] first and last row
	int polarity = 0;  //!< +1: darker on the left, -1: darker on the right
	double contrast = 0;  //!< mean |dI/du| along the segment [grey levels / px]
	double residual = 0;  //!< RMS of the column fit [px]
	size_t pixels = 0;	//!< edge pixels in the chain

	double vMid() const { return 0.5 * (vTop + vBottom); }
	double length() const { return vBottom - vTop + 1; }  //!< [px]
	double uAt(double v) const { return u + slope * (v - vMid()); }
};
}  // namespace featloc
