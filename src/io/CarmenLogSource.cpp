#include "featloc/io/CarmenLogSource.h"

#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/system/string_utils.h>

#include <algorithm>

namespace featloc
{
CarmenLogSource::CarmenLogSource(const std::string& path, const CarmenLogReader::Options& options)
	: m_path(path), m_scans(CarmenLogReader::read(path, options))
{
	// Some logs carry no usable time (orebro: all 0; belgioioso: 1.01893e+09
	// on every line, 6 significant digits): number their scans instead, so
	// they still run; the reference poses get the same times.
	for (size_t i = 1; i < m_scans.size() && !m_numberedTimes; i++)
		m_numberedTimes = !(m_scans[i].time > m_scans[i - 1].time);
	if (m_numberedTimes)
		for (size_t i = 0; i < m_scans.size(); i++)
		{
			m_scans[i].time = static_cast<double>(i) * kNumberedPeriod;
			m_scans[i].scan->timestamp = mrpt::Clock::fromDouble(m_scans[i].time);
		}
	// A corrected log's odom fields are its reference poses: giving them as
	// odometry would hand the estimator the answer (every Radish
	// "-corrected" log; odometry alone would score 0 mm ATE).
	const bool corrected = std::all_of(m_scans.begin(), m_scans.end(),
		[](const CarmenScan& s) { return s.odometry == s.pose; });
	if (corrected)
	{
		m_stepsWithoutOdomMessages = static_cast<size_t>(std::count_if(m_scans.begin(),
			m_scans.end(), [](const CarmenScan& s) { return !s.odomMessages; }));
		m_odometry = m_stepsWithoutOdomMessages == 0 ? Odometry::OdomMessages : Odometry::None;
	}
}

bool CarmenLogSource::handles(const std::string& path)
{
	const std::string p = mrpt::system::lowerCase(path);
	auto ends = [&](const std::string& s) {
		return p.size() >= s.size() && p.compare(p.size() - s.size(), s.size(), s) == 0;
	};
	return ends(".log") || ends(".log.gz");
}

bool CarmenLogSource::next(RawlogEntry& entry)
{
	if (m_next >= 2 * m_scans.size()) return false;
	if (m_next % 2 == 0 && m_odometry == Odometry::None) m_next++;  // no odometry to give
	const CarmenScan& s = m_scans[m_next / 2];
	entry.index = m_next;
	if (m_next % 2 == 0)
	{
		auto odo = std::make_shared<mrpt::obs::CObservationOdometry>();
		odo->sensorLabel = "ODOMETRY";
		odo->timestamp = s.scan->timestamp;
		odo->odometry = mrpt::poses::CPose2D(
			m_odometry == Odometry::OdomMessages ? *s.odomMessages : s.odometry);
		entry.object = odo;
	}
	else
		entry.object = s.scan;
	m_next++;
	return true;
}

double CarmenLogSource::progress() const
{
	return m_scans.empty() ? 1.0
						   : static_cast<double>(m_next) / static_cast<double>(2 * m_scans.size());
}

std::string CarmenLogSource::description() const
{
	std::string d = "CARMEN log, " + std::to_string(m_scans.size()) + " scans";
	if (m_numberedTimes)
		d += "; its times do not increase, so the scans were numbered 1 s apart (the "
			 "real-time figures of this run mean nothing)";
	switch (m_odometry)
	{
		case Odometry::FlaserFields:
			d += "; odometry: the FLASER messages' odom fields";
			break;
		case Odometry::OdomMessages:
			d += "; odometry: the ODOM messages (a corrected log: its FLASER odom fields are "
				 "the corrected poses)";
			break;
		case Odometry::None:
			d += "; no odometry: a corrected log (its FLASER odom fields are the corrected "
				 "poses) whose ODOM messages miss " +
				std::to_string(m_stepsWithoutOdomMessages) + " of " +
				std::to_string(m_scans.size()) + " scans";
			break;
	}
	return d;
}
}  // namespace featloc
