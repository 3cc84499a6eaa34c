#pragma once
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>

#include <functional>
#include <string>

namespace featloc::test
{
/** Writes small rawlogs with known ground truth for tests: a robot moving
 * along `path(t)` in SyntheticRoom::office(), exact scans, exact odometry. */
struct TestRawlog
{
	size_t scans = 10;
	double scanPeriod = 0.1;  //!< [s]
	double t0 = 1000.0;	 //!< first scan time [s]
	bool observationsOnly = false;	//!< format #2 (else #1)
	bool compress = true;
	/** Format #2: odometry readings per scan period (not synchronised with
	 * the scans: they start half a period before the first scan). */
	size_t odometryPerScan = 3;
	/** Format #2: false writes the scans alone (a robot without odometry). */
	bool odometry = true;
	/** Format #1: each action's timestamp is its scan's plus this [s]; NaN
	 * leaves the actions unstamped (as MRPT's simulated log does). */
	double actionTimeOffset = 0;
	std::string laserLabel = "LASER";
	/** Robot pose at time t (seconds after t0). */
	std::function<mrpt::poses::CPose2D(double)> path = [](double t) {
		return mrpt::poses::CPose2D(0.4 * t, 0.1 * std::sin(t), 0.15 * t);
	};
	/** Called on every scan before it is written (to damage it, relabel
	 * it...). */
	std::function<void(size_t, mrpt::obs::CObservation2DRangeScan&)> editScan;

	/** Writes the file; returns the scan times. */
	std::vector<double> write(const std::string& file) const;
};
}  // namespace featloc::test
