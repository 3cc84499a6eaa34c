#pragma once
#include <vector>

#include "featloc/io/CarmenLogReader.h"
#include "featloc/io/EntrySource.h"

namespace featloc
{
/** A CARMEN log (`.log` or `.log.gz`, e.g. the Radish logs) as an
 * EntrySource of rawlog format #2: for every FLASER message a
 * CObservationOdometry and the CObservation2DRangeScan, both at its logger
 * time. The odometry is the FLASER's odom_x odom_y odom_theta, except in a
 * corrected log (every FLASER's odom fields equal its corrected pose: they
 * are the reference, not odometry), where it is the wheel odometry of the
 * ODOM messages (CarmenScan::odomMessages); when those miss a step, the
 * log has no odometry featloc can use, and none is given (every step gets
 * the no-odometry prior). description() says which. The log is parsed
 * whole when the source is made, so a malformed line is an InputError
 * before the run starts. The corrected poses of the log (x y theta) are
 * kept as its reference trajectory. A log whose times do not strictly
 * increase (some Radish logs have none) gets its scans numbered
 * kNumberedPeriod apart, and description() says so. */
class CarmenLogSource : public EntrySource
{
   public:
	explicit CarmenLogSource(
		const std::string& path, const CarmenLogReader::Options& options = {});

	/** True for file names ending in .log or .log.gz (any case). */
	static bool handles(const std::string& path);

	bool next(RawlogEntry& entry) override;
	double progress() const override;
	std::string name() const override { return m_path; }
	std::string description() const override;

	const std::vector<CarmenScan>& scans() const { return m_scans; }

	static constexpr double kNumberedPeriod = 1.0;	//!< [s]

   private:
	std::string m_path;
	std::vector<CarmenScan> m_scans;
	size_t m_next = 0;	//!< next entry: 2 per scan (odometry, then scan)
	bool m_numberedTimes = false;
	enum class Odometry
	{
		FlaserFields,
		OdomMessages,
		None
	} m_odometry = Odometry::FlaserFields;
	size_t m_stepsWithoutOdomMessages = 0;
};
}  // namespace featloc
