#include "featloc/app/RunOutputs.h"

#include "featloc/app/RunConfiguration.h"
#include "featloc/localization/MapLocalizer.h"
#include "featloc/output/EstimatedRawlogWriter.h"
#include "featloc/output/LandmarkTableWriter.h"
#include "featloc/output/MatchTableWriter.h"
#include "featloc/output/PoseCovarianceWriter.h"
#include "featloc/output/ResultsFolder.h"
#include "featloc/output/ScanMapSceneWriter.h"
#include "featloc/output/SimpleMapWriter.h"
#include "featloc/output/StereoDebugPictureWriter.h"
#include "featloc/output/StereoFeatureTableWriter.h"
#include "featloc/output/StereoWallTableWriter.h"
#include "featloc/output/SummaryJsonWriter.h"
#include "featloc/output/TumTrajectoryWriter.h"

namespace featloc
{
std::vector<RunOutput*> RunOutputs::pointers() const
{
	std::vector<RunOutput*> out;
	for (const auto& o : owned) out.push_back(o.get());
	return out;
}

RunOutputs RunOutputs::make(const RunConfiguration& rc, const ResultsFolder& folder,
	bool withLandmarks, bool withEvaluation, const std::vector<std::string>& extraFiles)
{
	RunOutputs o;
	auto add = [&](std::unique_ptr<RunOutput> out, const std::string& name) {
		o.owned.push_back(std::move(out));
		o.names.push_back(name);
	};
	add(std::make_unique<TumTrajectoryWriter>(folder.stagedFile("trajectory.tum")),
		"trajectory.tum");
	add(std::make_unique<PoseCovarianceWriter>(folder.stagedFile("poses_cov.txt")),
		"poses_cov.txt");
	add(std::make_unique<MatchTableWriter>(folder.stagedFile("matches.txt")), "matches.txt");
	if (rc.output.write_rawlog)
		add(std::make_unique<EstimatedRawlogWriter>(
				folder.stagedFile("estimated.rawlog"), rc.output.pose_label),
			"estimated.rawlog");
	if (rc.output.write_scene)
		add(std::make_unique<ScanMapSceneWriter>(folder.stagedFile("map.3Dscene"),
				rc.output.scene_scan_decimation, rc.output.scene_point_resolution,
				rc.output.scene_ellipse_every,
				rc.mapLocalizer ? rc.mapLocalizer->map().occupiedCells()
								: std::vector<mrpt::math::TPoint2D>{}),
			"map.3Dscene");
	if (rc.output.write_simplemap)
		add(std::make_unique<SimpleMapWriter>(folder.stagedFile("map.simplemap")), "map.simplemap");
	if (withLandmarks)
		add(std::make_unique<LandmarkTableWriter>(folder.stagedFile("landmarks.txt")),
			"landmarks.txt");
	if (rc.stereo)
	{
		add(std::make_unique<StereoFeatureTableWriter>(folder.stagedFile("stereo_features.txt")),
			"stereo_features.txt");
		add(std::make_unique<StereoWallTableWriter>(folder.stagedFile("stereo_walls.txt")), "stereo_walls.txt");
		if (rc.output.stereo_debug_every > 0)
			add(std::make_unique<StereoDebugPictureWriter>(
					folder.stagedFile("stereo_debug"), rc.output.stereo_debug_every),
				"stereo_debug");
	}
	for (const auto& f : extraFiles) o.names.push_back(f);
	// Written after the run (see evaluateAndPlot), listed here so that
	// summary.json names every file of the folder.
	if (withEvaluation) o.names.push_back("nees.txt");
	o.names.push_back("trajectory.png");
	o.names.push_back("config_used.ini");
	o.names.push_back("summary.json");
	auto summary =
		std::make_unique<SummaryJsonWriter>(folder.stagedFile("summary.json"), o.names);
	o.summary = summary.get();
	o.owned.push_back(std::move(summary));
	return o;
}

}  // namespace featloc
