#pragma once
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPosePDFGaussian.h>

#include <cstddef>
#include <vector>

#include "featloc/ekf/LandmarkObservation.h"

namespace featloc
{
/** One laser scan to process, with the robot motion since the previous
 * processed scan as measured by odometry. Steps come in strictly increasing
 * scan time. */
struct ScanStep
{
	size_t scanIndex = 0;  //!< 0-based among the selected scans
	size_t entryIndex = 0;	//!< rawlog entry holding the scan
	/** The scan to use (a cleaned copy when beams were invalidated). */
	mrpt::obs::CObservation2DRangeScan::Ptr scan;
	/** The observation as stored in the rawlog (identifies it for output). */
	const mrpt::obs::CObservation* source = nullptr;
	/** False for the first scan, and when no odometry covers this step: then
	 * `odometry` is zero motion with the [Odometry] no_odometry_* sigmas
	 * (identity with zero covariance for the first scan). */
	bool hasOdometry = false;
	/** Robot motion from the previous step's scan to this one (robot frame of
	 * the previous scan), with covariance. */
	mrpt::poses::CPosePDFGaussian odometry;
	/** Point landmarks observed since the previous step (range-bearing
	 * observations of the rawlog; applied at this scan's time). */
	std::vector<LandmarkObservation> landmarks;

	mrpt::Clock::time_point timestamp() const { return scan->timestamp; }
};
}  // namespace featloc
