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
 * min_gap non-plane pixels, outward), if the SAD image sees something
 * else after it that is not nearer than the plane (an occluder hides
 * the end; see evidence_px, occluder_px: featloc's addition). A virtual mean m is moved over the
 * window in 0.1 px steps and the variance of the boundary pixels about it
 * computed; the boundary is the m of minimum variance and its sigma the
 * square root of that variance (the rows' spread, not the spread /
 * sqrt(rows)) plus, in quadrature, SAD fattening: the surface in front
 * carries its disparity up to half a block past its end in every row, a
 * bias the spread does not show (uniform on [0, block/2]: sigma
 * block / (2 sqrt 3)); at least sigma_img.
 *
 * The paper's rule: a boundary inward of the outermost segment on the
 * plane is moved to that segment. Only segments at least
 * min_edge_fraction as tall as the plane there count (featloc: on a
 * textured surface the outermost texture edge is not its end). With snap_to_segment (featloc's
 * addition, on by default), an outermost segment within 3 sigma outward
 * of the disparity boundary is taken as the boundary too, with
 * sigma_img: the intensity edge of the plane's end is sharper than the
 * SAD disparity's. Without a disparity boundary in the window (the plane
 * continues, e.g. a whiteboard on a wall), the outermost segment in the
 * window is the boundary if the caller allows it (segmentAlone); without
 * either, there is none. */
class BoundarySearch
{
   public:
	struct Options
	{
		double sigma_img = 0.5;	 //!< [px]
		double window_sigmas = 3;
		int min_gap = 3;  //!< [px] non-plane run that ends the plane in a row
		unsigned int min_rows = 10;
		/** ... and at least this fraction of the rows the wall covers at
		 * its end: a few textured rows of a blank wall are no boundary. */
		double min_row_fraction = 0.25;
		/** [px] a row's plane end counts only if a valid disparity off the
		 * plane (or the image border) follows within this many pixels:
		 * where a wall's texture fades, its SAD pixels stop without the
		 * wall ending. */
		int evidence_px = 12;
		/** [px] that valid disparity, if larger than the plane's last
		 * pixel's by more than this, is an occluder in front of the
		 * plane: the row is not a boundary row. */
		double occluder_px = 1.0;
		bool snap_to_segment = true;
		/** A segment is a candidate edge only if at least this fraction
		 * of the rows where the plane reaches the window long. */
		double min_edge_fraction = 0.5;
		int block_size = 15;  //!< [px] of the SAD matcher (its fattening)
	};
	BoundarySearch() = default;
	explicit BoundarySearch(const Options& o) : options(o) {}
	Options options;

	struct Result
	{
		bool found = false;
		bool atA = true;  //!< at the region's end a (else b)
		double u = 0, sigma = 0;  //!< [px] left-image column and its sigma
		/** [px] the minimum-variance boundary of the disparity alone and
		 * its sigma, before any segment rule (0 when there is none). */
		double uDisparity = 0, sigmaDisparity = 0;
		size_t rows = 0;  //!< rows with a disparity boundary
		size_t occludedRows = 0;  //!< rows where something nearer hid the plane's end
		size_t textureEnds = 0;	 //!< rows where the plane's pixels stopped with nothing else seen after
		std::string method;	 //!< "disparity", "outer segment", "disparity, snapped to segment"
	};

	/** The boundary at end a (atA) or b of `region`; `segmentColumns` are
	 * the left-image columns of the segments found on the plane and
	 * `segmentLengths` their lengths [px] (empty: any length);
	 * `disparity` the SAD image (empty: no evidence check); `expectedRows`
	 * how many image rows the wall spans at that end; `segmentAlone`:
	 * whether an outer segment may be the boundary without a disparity
	 * boundary (true only where the map continues the plane past the end,
	 * as a wall behind a whiteboard: elsewhere the disparity must show the
	 * end, and a texture edge in a 3-sigma window of a wall seen at a
	 * grazing angle is metres from the corner). */
	Result search(const PlanarRegion& region, const cv::Mat& disparity, bool atA,
		const std::vector<double>& segmentColumns, const std::vector<double>& segmentLengths = {},
		double expectedRows = 0, bool segmentAlone = true) const;
};
}  // namespace featloc
