#include "featloc/io/CarmenLogSource.h"

#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/system/string_utils.h>

namespace featloc
{
CarmenLogSource::CarmenLogSource(const std::string& path)
	: m_path(path), m_scans(CarmenLogReader::read(path, {}))
{
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
	const CarmenScan& s = m_scans[m_next / 2];
	entry.index = m_next;
	if (m_next % 2 == 0)
	{
		auto odo = std::make_shared<mrpt::obs::CObservationOdometry>();
		odo->sensorLabel = "ODOMETRY";
		odo->timestamp = s.scan->timestamp;
		odo->odometry = mrpt::poses::CPose2D(s.odometry);
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
	return "CARMEN log, " + std::to_string(m_scans.size()) + " scans";
}
}  // namespace featloc
