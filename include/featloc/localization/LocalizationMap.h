#pragma once
#include <mrpt/math/TPoint2D.h>
#include <mrpt/obs/obs_frwds.h>
#include <mrpt/poses/CPose2D.h>

#include <memory>
#include <string>
#include <vector>

namespace mrpt::maps
{
class COccupancyGridMap2D;
}

namespace featloc
{
/** A known 2-D map to localize in, whatever file it came from
 * (LocalizationMapFile): an MRPT occupancy grid, in the map's frame.
 *
 * It gives a matcher its reference the way a scan would: virtualScan()
 * casts the current scan's beams from a predicted pose into the grid
 * (MRPT's COccupancyGridMap2D::laserScanSimulator), so every registered
 * matcher matches scan-to-map exactly as it matches scan-to-scan, with
 * bearing-ordered points and the same beam geometry. */
class LocalizationMap
{
   public:
	/** `gridOffset`: where the map frame's origin lies in the grid's frame
	 * (a drawn map's grid is shifted so that walls on round coordinates run
	 * through cell centres). */
	LocalizationMap(
		std::shared_ptr<const mrpt::maps::COccupancyGridMap2D> grid, std::string path,
		std::string kind, mrpt::math::TPoint2D gridOffset = {0, 0});

	/** The scan `like` (its aperture, beams, direction, max range and
	 * sensor pose) would see from `robotPose` in this map. Beams that hit
	 * nothing within the max range are invalid. */
	mrpt::obs::CObservation2DRangeScan virtualScan(
		const mrpt::obs::CObservation2DRangeScan& like, const mrpt::poses::CPose2D& robotPose) const;

	/** The share of `scan`'s valid beams that reach farther than this map
	 * lets them from `robotPose` (virtualScan) by more than
	 * kSeeThroughMargin, or kSeeThroughShare of the map's range if that is
	 * more (a slightly wrong pose moves a grazing beam's end a long way):
	 * beams that pass through a wall or an obstacle the map has there. 0
	 * for a scan without valid beams. */
	double shareSeenThrough(
		const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::poses::CPose2D& robotPose) const;
	/** Which of `scan`'s valid beams (valid, 0 < range < maxRange, in beam
	 * order) reach farther than the map lets them from `robotPose`, by the
	 * margin shareSeenThrough uses. */
	std::vector<bool> beamsSeenThrough(
		const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::poses::CPose2D& robotPose) const;
	/** The share of true entries of beamsSeenThrough's result (0 when it is
	 * empty): shareSeenThrough without casting the rays again. */
	static double shareOf(const std::vector<bool>& seenThrough);
	static constexpr double kSeeThroughMargin = 0.3;  //!< [m]
	static constexpr double kSeeThroughShare = 0.1;

	/** Centres of the occupied cells (map frame), for pictures and the
	 * global search; found once, when the map is made. */
	const std::vector<mrpt::math::TPoint2D>& occupiedCells() const { return m_occupied; }

	/** The grid, in its own frame: map point p is grid point p + gridOffset(). */
	const mrpt::maps::COccupancyGridMap2D& grid() const { return *m_grid; }
	const mrpt::math::TPoint2D& gridOffset() const { return m_gridOffset; }
	const std::string& path() const { return m_path; }
	/** "simplemap", "gridmap", "image" or "world". */
	const std::string& kind() const { return m_kind; }
	/** "office.ini (world, 2000 x 800 cells of 0.020 m)". */
	std::string describe() const;

	/** A cell whose occupancy probability exceeds this stops a virtual
	 * beam. */
	static constexpr float kOccupiedThreshold = 0.6f;

   private:
	std::shared_ptr<const mrpt::maps::COccupancyGridMap2D> m_grid;
	std::string m_path, m_kind;
	mrpt::math::TPoint2D m_gridOffset;
	std::vector<mrpt::math::TPoint2D> m_occupied;
};
}  // namespace featloc
