#include "featloc/output/OutputOptions.h"

#include "featloc/config/ConfigValues.h"

namespace featloc
{
void OutputOptions::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	using namespace featloc::config;
	read(c, s, "dir", dir);
	read(c, s, "write_rawlog", write_rawlog);
	read(c, s, "write_scene", write_scene);
	read(c, s, "write_simplemap", write_simplemap);
	read(c, s, "pose_label", pose_label);
	read(c, s, "scene_scan_decimation", scene_scan_decimation);
	read(c, s, "scene_point_resolution", scene_point_resolution);
	read(c, s, "scene_ellipse_every", scene_ellipse_every);
	read(c, s, "stereo_debug_every", stereo_debug_every);
	require(!dir.empty(), c, s, "dir", "a folder name");
	require(!pose_label.empty(), c, s, "pose_label", "a non-empty label");
	require(scene_scan_decimation >= 1, c, s, "scene_scan_decimation", ">= 1");
	require(scene_point_resolution >= 0 && scene_point_resolution <= 10, c, s,
		"scene_point_resolution", "in [0, 10] m");
}

void OutputOptions::saveToConfigFile(
	mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	using namespace featloc::config;
	write(c, s, "dir", dir, "results folder; relative to this ini's folder");
	write(c, s, "write_rawlog", write_rawlog,
		"write estimated.rawlog (input + estimated poses)");
	write(c, s, "write_scene", write_scene,
		"write map.3Dscene (scans at estimated poses)");
	write(c, s, "write_simplemap", write_simplemap,
		"write map.simplemap (keyframe scans at estimated poses: a [Localization] map)");
	write(c, s, "pose_label", pose_label,
		"sensor label of the pose observations in estimated.rawlog");
	write(c, s, "scene_scan_decimation", scene_scan_decimation,
		"map.3Dscene shows every N-th scan");
	write(c, s, "scene_point_resolution", scene_point_resolution,
		"[m] map.3Dscene keeps one scan point per cell of this size (its memory grows with the area "
		"seen, not the log's length; 0: every point)");
	write(c, s, "scene_ellipse_every", scene_ellipse_every,
		"map.3Dscene: robot 3-sigma ellipse every N-th scan (0: none)");
	write(c, s, "stereo_debug_every", stereo_debug_every,
		"with stereo landmarks: stereo_debug/<step>.png for every N-th stereo pair (0: none)");
}
}  // namespace featloc
