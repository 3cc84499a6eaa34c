#include "featloc/stereo/BoundarySearch.h"

#include <algorithm>
#include <cmath>

namespace featloc
{
BoundarySearch::Result BoundarySearch::search(const PlanarRegion& region, const cv::Mat& disparity, bool atA,
	const std::vector<double>& segmentColumns, const std::vector<double>& segmentLengths, double expectedRows,
	bool segmentAlone) const
{
	Result res;
	res.atA = atA;
	if (region.mask.empty()) return res;
	const double uE = atA ? region.uA : region.uB, sE = atA ? region.sigmaUA : region.sigmaUB;
	const double uOther = atA ? region.uB : region.uA;
	const int outward = uOther > uE ? -1 : 1;  // image direction leaving the plane
	const int W = region.mask.cols;
	const double half = options.window_sigmas * sE;
	const int wl = std::max(0, static_cast<int>(std::floor(uE - half)));
	const int wr = std::min(W - 1, static_cast<int>(std::ceil(uE + half)));
	if (wr - wl < 1) return res;
	const int inner = outward > 0 ? wl : wr, outer = outward > 0 ? wr : wl;

	std::vector<double> b;
	size_t planeRows = 0;  // rows where the plane fills the window's inner edge
	for (int v = 0; v < region.mask.rows; v++)
	{
		const uchar* m = region.mask.ptr<uchar>(v);
		const float* d = disparity.empty() ? nullptr : disparity.ptr<float>(v);
		// The plane must fill the window's inner edge (within 2 px).
		int start = -1;
		for (int k = 0; k <= 2; k++)
		{
			const int u = inner - outward * k;
			if (u >= 0 && u < W && m[u]) start = u;
			if (start >= 0) break;
		}
		if (start < 0) continue;
		planeRows++;
		int last = start, gap = 0;
		bool ended = false;
		for (int u = start; (outward > 0 ? u <= outer : u >= outer); u += outward)
		{
			if (m[u])
			{
				last = u;
				gap = 0;
			}
			else if (++gap >= options.min_gap)
			{
				ended = true;
				break;
			}
		}
		if (!ended) continue;
		// Evidence that the plane ends here, not only its texture: past
		// its last pixel the SAD image sees something else (a valid
		// disparity off the plane) within evidence_px, or the image ends.
		// Something nearer than the plane there occludes it: its end is
		// hidden, and the row says nothing about where it is.
		bool seen = d == nullptr, occluded = false;
		for (int k = 1; !seen && k <= options.evidence_px; k++)
		{
			const int u = last + outward * k;
			if (u < 0 || u >= W)
				seen = true;
			else if (d[u] > 0 && !m[u])
			{
				seen = true;
				occluded = d[u] > d[last] + options.occluder_px;
			}
		}
		if (seen && !occluded)
			b.push_back(last + 0.5 * outward);
		else if (occluded)
			res.occludedRows++;
		else
			res.textureEnds++;
	}
	res.rows = b.size();

	// The outermost segment in the window.
	double outerSeg = 0;
	bool hasSeg = false;
	// Only a segment as tall as a good part of the plane there can be its
	// edge: a textured surface has short texture edges near its end.
	for (size_t i = 0; i < segmentColumns.size(); i++)
	{
		const double u = segmentColumns[i];
		const double len = i < segmentLengths.size() ? segmentLengths[i] : 1e9;
		if (len < options.min_edge_fraction * static_cast<double>(planeRows)) continue;
		if (u >= wl - 0.5 && u <= wr + 0.5 && (!hasSeg || (u - outerSeg) * outward > 0)) outerSeg = u, hasSeg = true;
	}

	if (b.size() >= options.min_rows && static_cast<double>(b.size()) >= options.min_row_fraction * expectedRows)
	{
		// Minimum variance over virtual means in the window.
		double bestV = 1e300, bestM = uE;
		for (double m = wl; m <= wr; m += 0.1)
		{
			double v = 0;
			for (double x : b) v += (x - m) * (x - m);
			v /= static_cast<double>(b.size());
			if (v < bestV) bestV = v, bestM = m;
		}
		res.found = true;
		res.u = res.uDisparity = bestM;
		// SAD fattening: the surface in front carries its disparity up to
		// half a block past its end, the same in every row: a bias the
		// rows' spread does not show. As a uniform error on [0, block/2]
		// its sigma is block / (2 sqrt 3).
		const double fat = options.block_size / (2 * std::sqrt(3.0));
		res.sigma = res.sigmaDisparity = std::max(options.sigma_img, std::sqrt(bestV + fat * fat));
		res.method = "disparity";
		if (hasSeg)
		{
			const double out = (outerSeg - res.u) * outward;  // > 0: segment outward
			if (out < 0)
			{
				res.u = outerSeg;  // the paper's rule
				res.sigma = options.sigma_img;
				res.method = "disparity inside the outer segment: segment";
			}
			else if (options.snap_to_segment && out <= options.window_sigmas * res.sigma)
			{
				res.u = outerSeg;
				res.sigma = options.sigma_img;
				res.method = "disparity, snapped to segment";
			}
		}
		return res;
	}
	if (hasSeg && segmentAlone)
	{
		res.found = true;
		res.u = outerSeg;
		res.sigma = options.sigma_img;
		res.method = "outer segment";
	}
	return res;
}
}  // namespace featloc
