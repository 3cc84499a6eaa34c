#pragma once
#include <mrpt/config/CLoadableOptions.h>

#include <string>

namespace featloc
{
/** `[Output]`: where results go and which optional files are written.
 * trajectory.tum, poses_cov.txt and summary.json are always written. */
struct OutputOptions : public mrpt::config::CLoadableOptions
{
	static constexpr const char* kSection = "Output";

	/** Results folder (created if missing). Relative: to the ini's folder.
	 * --out overrides it. */
	std::string dir = "results";
	bool write_rawlog = true;  //!< estimated.rawlog
	bool write_scene = true;  //!< map.3Dscene
	/** map.simplemap: the keyframe scans at their estimated poses (MRPT's
	 * CSimpleMap), the next run's [Localization] map. */
	bool write_simplemap = true;
	/** Sensor label of the CObservationRobotPose added to the rawlog. */
	std::string pose_label = "featloc_estimate";
	/** map.3Dscene holds the points of every N-th scan. */
	unsigned int scene_scan_decimation = 1;
	/** [m] map.3Dscene keeps the first scan point that falls in each cell
	 * of this size: the scene (and the run's memory) grows with the area
	 * seen, not with the log's length (0: every point, as many as the log
	 * has). */
	double scene_point_resolution = 0.02;
	/** map.3Dscene draws the robot's 3-sigma covariance ellipse at every
	 * N-th scan (0: none); landmarks always get theirs. */
	unsigned int scene_ellipse_every = 10;
	/** With stereo landmarks: stereo_debug/<step>.png, the left image of
	 * every N-th stereo pair with detected, matched, on-plane and selected
	 * segments (Moon et al.'s Figs. 5-6; 0: none). */
	unsigned int stereo_debug_every = 0;

	void loadFromConfigFile(
		const mrpt::config::CConfigFileBase& c,
		const std::string& s) override;
	void saveToConfigFile(
		mrpt::config::CConfigFileBase& c, const std::string& s) const override;
};
}  // namespace featloc
