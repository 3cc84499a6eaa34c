#include "featloc/output/LandmarkTableWriter.h"
#include "featloc/core/WholeFile.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>

#include "featloc/output/TextRowWriter.h"

namespace featloc
{
void LandmarkTableWriter::onStep(const StepRecord& r)
{
	if (r.landmarks) m_landmarks = *r.landmarks;
}

void LandmarkTableWriter::finish(const RunStats&)
{
	writeWholeFile(m_path, [&](const std::string& file) { writeTable(file); });
}

void LandmarkTableWriter::writeTable(const std::string& file) const
{
	std::ofstream f(file);
	if (!f) throw std::runtime_error("cannot write '" + m_path + "'");
	f << "# featloc EKF landmarks (world frame): id x y c_xx c_xy c_yy "
		 "observations kind plane l_low l_high l sigma_x sigma_y sigma_l_low sigma_l_high\n"
		 "# (m, m^2; id -1: none from the sensor; kind point | vertical: a vertical line of Moon, "
		 "Miura & Shirai on the map wall `plane`, its ends' heights l_low l_high and l = l_high - l_low as in "
		 "their Table 1; '-' where it does not apply)\n";
	char row[512];
	for (const auto& l : m_landmarks)
	{
		int n = std::snprintf(
			row, sizeof(row), "%lld %.6f %.6f %.6e %.6e %.6e %u", static_cast<long long>(l.id), l.mean.x(),
			l.mean.y(), l.covariance(0, 0), l.covariance(0, 1), l.covariance(1, 1), l.observations);
		if (l.vertical)
			std::snprintf(row + n, sizeof(row) - static_cast<size_t>(n),
				" vertical %s %.4f %.4f %.4f %.5f %.5f %.5f %.5f\n", TextRowWriter::token(l.plane).c_str(),
				l.lLow, l.lHigh, l.lHigh - l.lLow, std::sqrt(l.covariance(0, 0)), std::sqrt(l.covariance(1, 1)),
				l.sigmaLow, l.sigmaHigh);
		else
			std::snprintf(row + n, sizeof(row) - static_cast<size_t>(n), " point - - - - %.5f %.5f - -\n",
				std::sqrt(l.covariance(0, 0)), std::sqrt(l.covariance(1, 1)));
		f << row;
	}
	f.close();
	if (!f) throw std::runtime_error("error writing '" + m_path + "'");
}
}  // namespace featloc
