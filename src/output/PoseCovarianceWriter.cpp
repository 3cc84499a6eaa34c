#include "featloc/output/PoseCovarianceWriter.h"

#include <mrpt/core/Clock.h>

#include <cstdio>
#include <stdexcept>

namespace featloc
{
PoseCovarianceWriter::PoseCovarianceWriter(std::string path)
	: m_path(std::move(path)), m_out(m_path)
{
	if (!m_out) throw std::runtime_error("cannot write '" + m_path + "'");
	m_out << "# featloc poses with covariance: t x y yaw c_xx c_xy c_xyaw "
			 "c_yy c_yyaw c_yawyaw (m, rad)\n";
}

void PoseCovarianceWriter::onStep(const StepRecord& r)
{
	const auto& m = r.pose.mean;
	const auto& c = r.pose.cov;
	char line[512];
	std::snprintf(
		line, sizeof(line),
		"%.9f %.9f %.9f %.12f %.9e %.9e %.9e %.9e %.9e %.9e\n",
		mrpt::Clock::toDouble(r.step.timestamp()), m.x(), m.y(), m.phi(),
		c(0, 0), c(0, 1), c(0, 2), c(1, 1), c(1, 2), c(2, 2));
	m_out << line << std::flush;
}

void PoseCovarianceWriter::finish(const RunStats&) { m_out.close(); }
}  // namespace featloc
