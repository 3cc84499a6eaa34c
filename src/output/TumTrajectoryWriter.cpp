#include "featloc/output/TumTrajectoryWriter.h"

#include <mrpt/core/Clock.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace featloc
{
TumTrajectoryWriter::TumTrajectoryWriter(std::string path)
	: m_path(std::move(path)), m_out(m_path)
{
	if (!m_out) throw std::runtime_error("cannot write '" + m_path + "'");
	m_out << "# featloc trajectory (TUM format): t x y z qx qy qz qw\n";
}

void TumTrajectoryWriter::onStep(const StepRecord& r)
{
	const auto& m = r.pose.mean;
	char line[256];
	std::snprintf(
		line, sizeof(line), "%.9f %.9f %.9f 0 0 0 %.12f %.12f\n",
		mrpt::Clock::toDouble(r.step.timestamp()), m.x(), m.y(),
		std::sin(m.phi() / 2), std::cos(m.phi() / 2));
	m_out << line << std::flush;
}

void TumTrajectoryWriter::finish(const RunStats&) { m_out.close(); }
}  // namespace featloc
