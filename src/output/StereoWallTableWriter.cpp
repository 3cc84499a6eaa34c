#include "featloc/output/StereoWallTableWriter.h"

#include <cmath>
#include <cstdio>

#include "featloc/estimators/StereoStepResult.h"
#include "featloc/output/StepRecord.h"

namespace featloc
{
StereoWallTableWriter::StereoWallTableWriter(std::string path)
	: TextRowWriter(std::move(path),
		  "featloc stereo wall observations, one row per wall that observed the pose in a pair:\n"
		  "# step plane a b sigma_a sigma_b view_angle_deg coverage mahalanobis2 outcome\n"
		  "# (a [m], b: the wall's line w = a + b s fitted to its disparity pixels, in a frame fixed to the "
		  "robot at the wall's predicted end; mahalanobis2: against the map's wall seen from the EKF's "
		  "belief, 2 dof; outcome: used | failed its gate | dropped by the joint gate)")
{
}

void StereoWallTableWriter::onStep(const StepRecord& r)
{
	if (!r.stereo) return;
	const auto& walls = r.stereo->frame.walls;
	const auto& u = r.stereo->update;
	char row[512];
	for (size_t i = 0; i < walls.size(); i++)
	{
		const auto& w = walls[i];
		const bool known = i < u.wallOutcome.size();
		std::snprintf(row, sizeof(row), "%zu %s %.5f %.6f %.5f %.6f %.1f %.3f %.2f %s", r.step.index,
			token(w.plane).c_str(), w.line.x(), w.line.y(), std::sqrt(w.covariance(0, 0)),
			std::sqrt(w.covariance(1, 1)), w.viewAngle * 180 / M_PI, w.coverage,
			known ? u.wallMahalanobis2[i] : -1.0, known ? u.wallOutcome[i].c_str() : "-");
		writeRow(row);
	}
}
}  // namespace featloc
