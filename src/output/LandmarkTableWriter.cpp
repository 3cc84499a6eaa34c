#include "featloc/output/LandmarkTableWriter.h"

#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace featloc
{
void LandmarkTableWriter::onStep(const StepRecord& r)
{
	if (r.landmarks) m_landmarks = *r.landmarks;
}

void LandmarkTableWriter::finish(const RunStats&)
{
	std::ofstream f(m_path);
	if (!f) throw std::runtime_error("cannot write '" + m_path + "'");
	f << "# featloc EKF landmarks (world frame): id x y c_xx c_xy c_yy "
		 "observations (m, m^2; id -1: none from the sensor)\n";
	char row[256];
	for (const auto& l : m_landmarks)
	{
		std::snprintf(
			row, sizeof(row), "%lld %.6f %.6f %.6e %.6e %.6e %u\n",
			static_cast<long long>(l.id), l.mean.x(), l.mean.y(), l.covariance(0, 0),
			l.covariance(0, 1), l.covariance(1, 1), l.observations);
		f << row;
	}
}
}  // namespace featloc
