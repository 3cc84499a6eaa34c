#include "featloc/output/PoseCovarianceWriter.h"

#include <mrpt/core/Clock.h>

#include <cstdio>

namespace featloc
{
PoseCovarianceWriter::PoseCovarianceWriter(std::string path)
	: TextRowWriter(
		  std::move(path),
		  "featloc poses with covariance: t x y yaw c_xx c_xy c_xyaw c_yy "
		  "c_yyaw c_yawyaw (m, rad)")
{
}

void PoseCovarianceWriter::onStep(const StepRecord& r)
{
	const auto& m = r.pose.mean;
	const auto& c = r.pose.cov;
	char row[512];
	std::snprintf(
		row, sizeof(row), "%.9f %.9f %.9f %.12f %.9e %.9e %.9e %.9e %.9e %.9e",
		mrpt::Clock::toDouble(r.step.time), m.x(), m.y(), m.phi(),
		c(0, 0), c(0, 1), c(0, 2), c(1, 1), c(1, 2), c(2, 2));
	writeRow(row);
}
}  // namespace featloc
