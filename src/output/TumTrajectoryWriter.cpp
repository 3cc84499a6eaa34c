#include "featloc/output/TumTrajectoryWriter.h"

#include <mrpt/core/Clock.h>

#include <cmath>
#include <cstdio>

namespace featloc
{
TumTrajectoryWriter::TumTrajectoryWriter(std::string path)
	: TextRowWriter(
		  std::move(path),
		  "featloc trajectory (TUM format): t x y z qx qy qz qw")
{
}

void TumTrajectoryWriter::onStep(const StepRecord& r)
{
	const auto& m = r.pose.mean;
	char row[256];
	std::snprintf(
		row, sizeof(row), "%.9f %.9f %.9f 0 0 0 %.12f %.12f",
		mrpt::Clock::toDouble(r.step.time), m.x(), m.y(),
		std::sin(m.phi() / 2), std::cos(m.phi() / 2));
	writeRow(row);
}
}  // namespace featloc
