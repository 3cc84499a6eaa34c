#include "featloc/output/StereoFeatureTableWriter.h"

#include <cmath>
#include <cstdio>

#include "featloc/estimators/StereoStepResult.h"
#include "featloc/output/StepRecord.h"

namespace featloc
{
StereoFeatureTableWriter::StereoFeatureTableWriter(std::string path)
	: TextRowWriter(std::move(path),
		  "featloc stereo features (Moon, Miura & Shirai, Table 1), one row per modelled feature:\n"
		  "# step plane index x y l sigma_x sigma_y l_s selected landmark reason\n"
		  "# (world frame, m; index counted from the plane's boundary; landmark: the EKF landmark it "
		  "updated or started, -1 none; reason: why not selected)")
{
}

void StereoFeatureTableWriter::onStep(const StepRecord& r)
{
	if (!r.stereo) return;
	const auto& f = r.stereo->frame;
	char row[512];
	for (const auto& ft : f.features)
	{
		int landmark = -1;
		for (size_t k = 0; k < f.observations.size(); k++)
			if (f.observations[k].match == ft.match && k < r.stereo->update.landmarkOf.size())
				landmark = r.stereo->update.landmarkOf[k];
		std::snprintf(row, sizeof(row), "%zu %s %d %.4f %.4f %.4f %.5f %.5f %.3f %s %d %s", r.step.index,
			token(ft.plane).c_str(), ft.index, ft.position.x(), ft.position.y(), ft.length(),
			std::sqrt(ft.covariance(0, 0)), std::sqrt(ft.covariance(1, 1)), ft.lengthSimilarity,
			ft.selected ? "Yes" : "No", landmark, ft.reason.c_str());
		writeRow(row);
	}
}
}  // namespace featloc
