#pragma once
#include <mrpt/poses/CPose2D.h>

#include <cstdint>
#include <functional>
#include <vector>

namespace cv
{
class Mat;
}

namespace featloc
{
/** The lookup tables and branch and bound of Olson's multi-resolution
 * correlative scan matching ("Real-time correlative scan matching", ICRA
 * 2009, sections III-IV), whatever the reference is: a scan's surfaces
 * (CorrelativeScanSearch, the matchers' wide basin) or a map's occupied
 * cells (localization/GlobalMapSearch, global localization).
 *
 * Level 0 holds exp(-d^2 / 2 sigma_hit^2) per cell, d the distance to the
 * reference surface (OpenCV's distance transform, or buildNear's near the
 * surface only); level L holds the
 * maximum over the 2^L x 2^L cells at and above-right of each cell, so that
 * one lookup bounds every translation of a block of that side. A pose's
 * score is the mean table value under the points it places: the share of
 * the scan on the reference.
 *
 * Levels 1 and up hold that maximum rounded up to a multiple of 1/255 in
 * one byte, as Cartographer's precomputation grids do: a bound stays a
 * bound (a little looser), the search finds the same poses, and the tables
 * it reads at random take a quarter of the memory (a real log's scan spans
 * near a million cells per level, beyond the core's cache as floats). */
class CorrelationTables
{
   public:
	/** Levels of the branch and bound: blocks of up to 2^6 = 64 cells. */
	static constexpr int kMaxLevel = 6;
	/** The top level for a window of +-halfWindow [m]: up to 2 x 2 blocks
	 * across it per rotation. With a keyframe's tables kept (built once),
	 * 4 x 4 blocks scored 2050 bounds per office search, most of them the
	 * top blocks of rotations that are then dropped; 2 x 2 blocks score
	 * 1210 (PCM whole run 0.68 -> 0.58 ms per match, same trajectory). */
	static int topLevelFor(double halfWindow, double resolution);

	/** Olson's rotation step for points (px, py) around their frame's
	 * origin: the angle that moves the 95th-percentile-range point by one
	 * cell of `resolution` (the 95th percentile so that one stray return
	 * does not set it). */
	static double rotationStep(
		const std::vector<double>& px, const std::vector<double>& py, double resolution);

	/** Tables of `width` x `height` cells of `resolution` from (x0, y0),
	 * levels 0..top. `drawSurface` draws the reference surface as zero
	 * pixels into a CV_8U image of 255 (row v, column u: the cell from
	 * (x0 + u res, y0 + v res)). */
	void build(int width, int height, double x0, double y0, double resolution, double hitSigma,
		int top, const std::function<void(cv::Mat& surface)>& drawSurface);
	/** The same with distances known only up to `maxDistance` [m] (> 0):
	 * each surface pixel writes the cells within it, so the cost follows
	 * the surface's length instead of the table's area (a real log's scan
	 * spans tens of metres: millions of cells for a few thousand surface
	 * pixels). Within maxDistance the distances are the exact transform's
	 * and the table's values the same to float rounding; beyond,
	 * distanceAt() is infinite and the table 0, where the exact table holds
	 * at most exp(-maxDistance^2 / 2 hitSigma^2). */
	void buildNear(int width, int height, double x0, double y0, double resolution,
		double hitSigma, int top, double maxDistance,
		const std::function<void(cv::Mat& surface)>& drawSurface);

	/** Poses searched: centre (+) (dx res, dy res, dw yawStep) for
	 * |dx| <= nx, |dy| <= ny, |dw| <= nYaw (the translation is in the
	 * table's frame, not turned with the centre). */
	struct Window
	{
		mrpt::poses::CPose2D centre;
		int nx = 0, ny = 0, nYaw = 0;
		double yawStep = 0;
	};
	struct Candidate
	{
		mrpt::poses::CPose2D pose;
		double score = 0;  //!< mean table value under the points [0-1]
	};
	/** Branch and bound, best bound first (Olson section IV; each block
	 * split in four, as Cartographer's fast correlative matcher): every
	 * full-resolution pose of `w` whose score reaches keepRatio x the best,
	 * best first (keepRatio 1: the best only, and its equals). The points
	 * (px, py) are in the frame of the pose searched for. Poses for which
	 * `excluded` is true are skipped (a second search for the best rival
	 * of a solution). */
	std::vector<Candidate> search(const std::vector<double>& px, const std::vector<double>& py,
		const Window& w, double keepRatio,
		const std::function<bool(const mrpt::poses::CPose2D&)>& excluded = {}) const;

	/** Mean level-0 table value under the points placed by `pose`. */
	double score(const std::vector<double>& px, const std::vector<double>& py,
		const mrpt::poses::CPose2D& pose) const;

	/** Distance [m] from (x, y) to the surface, or a negative number
	 * outside the tables. */
	double distanceAt(double x, double y) const;

	bool empty() const { return m_table.empty(); }
	double resolution() const { return m_resolution; }
	int top() const { return m_top; }
	double x0() const { return m_x0; }
	double y0() const { return m_y0; }
	int width() const { return m_width; }
	int height() const { return m_height; }

   private:
	/** Sets the geometry, sizes the tables and returns the drawn surface. */
	cv::Mat prepare(int width, int height, double x0, double y0, double resolution, int top,
		const std::function<void(cv::Mat& surface)>& drawSurface);
	/** Levels 1..top from level 0. */
	void buildLevels();
	/** A level's cell value, rounded up, as a multiple of this. */
	static constexpr double kBoundScale = 255.0;
	/** Index of table cell (u, v) in the row-major tables, -1 outside. */
	long cellIndex(int u, int v) const;

	// Row-major, m_width x m_height cells of m_resolution from (m_x0, m_y0):
	// the full-resolution table, and [L] the maxima over blocks of 2^L in
	// units of 1 / kBoundScale, rounded up ([0], the table's own cells,
	// only builds [1]).
	std::vector<float> m_table;
	std::vector<std::vector<uint8_t>> m_bounds;
	std::vector<float> m_distance;	// [m] to the surface, full resolution
	int m_width = 0, m_height = 0, m_top = 0;
	double m_x0 = 0, m_y0 = 0, m_resolution = 0;
};
}  // namespace featloc
