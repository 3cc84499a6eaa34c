#include "TestRawlog.h"

#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/io/CFileOutputStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>

#include <cmath>
#include <memory>

#include "SyntheticRoom.h"

namespace featloc::test
{
std::vector<double> TestRawlog::write(const std::string& file) const
{
	using namespace mrpt::obs;
	std::unique_ptr<mrpt::io::CStream> out;
	if (compress)
		out = std::make_unique<mrpt::io::CFileGZOutputStream>(file);
	else
		out = std::make_unique<mrpt::io::CFileOutputStream>(file);
	auto arch = mrpt::serialization::archiveFrom(*out);
	const SyntheticRoom room = SyntheticRoom::office();
	std::vector<double> times;

	const double odoPeriod = scanPeriod / static_cast<double>(odometryPerScan);
	double nextOdo = -scanPeriod / 2;
	for (size_t k = 0; k < scans; k++)
	{
		const double t = scanPeriod * static_cast<double>(k);
		times.push_back(t0 + t);
		auto scan = room.scan(path(t), mrpt::poses::CPose2D(0.2, 0, 0));
		scan->sensorLabel = laserLabel;
		scan->timestamp = mrpt::Clock::fromDouble(t0 + t);
		if (editScan) editScan(k, *scan);

		if (observationsOnly)
		{
			for (; odometry && nextOdo <= t; nextOdo += odoPeriod)
			{
				CObservationOdometry odo;
				odo.sensorLabel = "ODOMETRY";
				odo.timestamp = mrpt::Clock::fromDouble(t0 + nextOdo);
				odo.odometry = path(nextOdo);
				arch << odo;
			}
			arch << *scan;
		}
		else
		{
			if (k > 0)
			{
				CActionRobotMovement2D move;
				CActionRobotMovement2D::TMotionModelOptions opts;
				move.computeFromOdometry(
					path(t) - path(t - scanPeriod), opts);
				if (!std::isnan(actionTimeOffset))
					move.timestamp = mrpt::Clock::fromDouble(
						mrpt::Clock::toDouble(scan->timestamp) + actionTimeOffset);
				CActionCollection acts;
				acts.insert(move);
				arch << acts;
			}
			CSensoryFrame sf;
			sf.insert(scan);
			arch << sf;
		}
	}
	// Format #2: odometry continues a little after the last scan, so the
	// last scan's time is bracketed too.
	if (observationsOnly && scans > 0)
	{
		const double tEnd = scanPeriod * static_cast<double>(scans);
		for (; odometry && nextOdo <= tEnd; nextOdo += odoPeriod)
		{
			CObservationOdometry odo;
			odo.sensorLabel = "ODOMETRY";
			odo.timestamp = mrpt::Clock::fromDouble(t0 + nextOdo);
			odo.odometry = path(nextOdo);
			arch << odo;
		}
	}
	return times;
}
}  // namespace featloc::test
