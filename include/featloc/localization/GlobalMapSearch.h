#pragma once
#include <mrpt/obs/obs_frwds.h>
#include <mrpt/poses/CPose2D.h>

#include <vector>

#include "featloc/localization/LocalizationMap.h"
#include "featloc/matchers/CorrelationTables.h"

namespace featloc
{
/** Where in the map could the robot be? A scan matched against the whole
 * map at every rotation: Olson's branch and bound (CorrelationTables) over
 * a lookup table of the map's occupied cells, as Cartographer's fast
 * correlative scan matcher does for global localization and loop closure.
 *
 * search() returns the best pose and its best rival: the best pose more
 * than a distinct distance away from it (a second branch and bound that
 * skips the first's neighbourhood). A scan the map explains in two places
 * (a corridor's two ends, two identical rooms) has a rival that scores
 * nearly as well: the caller waits for more scans (MapLocalizer). */
class GlobalMapSearch
{
   public:
	struct Options
	{
		double resolution = 0.05;  //!< [m] table cell and translation step
		double hitSigma = 0.10;	 //!< [m] width of the table around occupied cells
		unsigned int maxPoints = 120;  //!< scan points scored (evenly picked)
		double distinctXY = 0.5;  //!< [m] a rival is at least this far from the best
		double distinctYaw = 0.2617993877991494;  //!< [rad] (15 deg) or turned this much
		/** refine()'s table: finer and sharper, so that its scores tell
		 * similar places apart (the search's wide table makes its basin). */
		double refineResolution = 0.025;  //!< [m]
		double refineHitSigma = 0.04;  //!< [m]
		/** search() also returns up to this many other distinct places
		 * (`contenders`) scoring at least contenderRatio x the best: the
		 * look-alike rooms a hypothesis tracker must keep in view. 0: the
		 * rival only. */
		unsigned int maxContenders = 10;
		double contenderRatio = 0.85;
	};

	GlobalMapSearch(const LocalizationMap& map, const Options& options);

	struct Result
	{
		bool valid = false;	 //!< false: the scan has too few points
		mrpt::poses::CPose2D best;	//!< robot pose in the map
		double bestScore = 0;  //!< share of the scan's points on the map [0-1]
		mrpt::poses::CPose2D rival;
		double rivalScore = 0;	//!< 0 when nothing else scores
		/** Further distinct places, best first, after the rival. */
		std::vector<CorrelationTables::Candidate> contenders;
		double seconds = 0;
	};
	Result search(const mrpt::obs::CObservation2DRangeScan& scan) const;

	/** The best pose within +-halfXY, +-halfYaw of `around` and its score
	 * on the sharp table (refineResolution, refineHitSigma): a hypothesis
	 * moved by odometry, put back on the map and judged. */
	struct Local
	{
		mrpt::poses::CPose2D pose;
		double score = 0;
	};
	Local refine(const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::poses::CPose2D& around,
		double halfXY, double halfYaw) const;
	/** Each valid beam's (valid, 0 < range < maxRange, in beam order: as
	 * LocalizationMap::beamsSeenThrough) end point with the robot at
	 * `pose`, on the sharp table: exp(-d^2 / 2 refineHitSigma^2), d its
	 * distance to the nearest occupied cell; 0 off the table. */
	std::vector<double> beamHits(
		const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::poses::CPose2D& pose) const;


	const Options& options() const { return m_options; }

   private:
	/** The scan's valid points in the robot frame, evenly picked. */
	void robotFramePoints(const mrpt::obs::CObservation2DRangeScan& scan, std::vector<double>& x,
		std::vector<double>& y) const;

	Options m_options;
	CorrelationTables m_tables;
	CorrelationTables m_sharp;	// refine()'s
	double m_cx = 0, m_cy = 0;	// the map's centre
	int m_nx = 0, m_ny = 0;	 // half-widths of the map in cells
};
}  // namespace featloc
