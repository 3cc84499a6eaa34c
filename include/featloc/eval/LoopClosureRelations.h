#pragma once
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>

#include <map>
#include <string>
#include <vector>

#include "featloc/eval/Trajectory.h"
#include "featloc/matchers/ScanMatcher.h"

namespace featloc
{
/** A reference for logs without ground truth: where a trajectory comes back
 * to a place it passed much earlier, the two scans are matched directly.
 * One match across the loop is far more accurate than the chain of
 * matches (or odometry) that joins the two poses, so the relations it gives
 * (Kuemmerle et al. 2009's metric, featloc-eval's relations) measure the
 * drift each estimate accumulated around the loop.
 *
 * Revisits are taken from `trajectory` (associated with the scans by
 * time): for each scan i, the later scan j at least min_gap scans on whose
 * pose is nearest, if within max_distance and max_angle. The direct match
 * starts from the trajectory's own i-to-j motion with a covariance of
 * guess_sigma_xy / guess_sigma_yaw: give the matcher a wide-basin search
 * (coarse_search) so that the reference does not depend on that guess. */
class LoopClosureRelations
{
   public:
	struct Options
	{
		size_t min_gap = 50;  //!< [scans] between the two of a pair
		double max_distance = 1.0;	//!< [m] between their poses
		double max_angle = 0.5;	 //!< [rad] between their headings
		size_t stride = 1;	//!< every stride-th scan i is tried
		double guess_sigma_xy = 0.3;  //!< [m]
		double guess_sigma_yaw = 0.15;	//!< [rad]
	};

	struct Result
	{
		std::vector<PoseRelation> relations;  //!< the converged, unflagged matches
		size_t revisits = 0;  //!< pairs found in the trajectory
		size_t failed = 0;	//!< of which the match failed or was flagged ambiguous
		/** The failures by MatchResult::failureKind ("ambiguous" for the
		 * flagged ones), with one reason each. */
		std::map<std::string, size_t> failuresByKind;
		std::map<std::string, std::string> exampleByKind;
	};

	/** `scans` and `times` [s] in log order. */
	static Result find(const std::vector<mrpt::obs::CObservation2DRangeScan::Ptr>& scans,
		const std::vector<double>& times, const Trajectory& trajectory, ScanMatcher& matcher,
		const Options& options);

	/** Writes relations as featloc-eval reads them: "t1 t2 x y z roll pitch
	 * yaw" rows (z, roll, pitch 0). */
	static void write(const std::string& path, const std::vector<PoseRelation>& relations,
		const std::string& comment);
};
}  // namespace featloc
