#pragma once
#include <mrpt/config/CLoadableOptions.h>

#include <string>
#include <vector>

namespace featloc
{
/** `[Localization]`: localization in a known map (issue "Localization in a
 * known map"). With `map` empty the run estimates motion relative to its
 * start, as before; with a map every scan is also matched against the map
 * around the predicted pose and the EKF fuses the result as an absolute
 * pose (MapScanTracker), so the run does not drift. */
struct LocalizationOptions : public mrpt::config::CLoadableOptions
{
	static constexpr const char* kSection = "Localization";

	/** The map: an MRPT `.simplemap(.gz)` (a run's map.simplemap, icp-slam's
	 * output), an MRPT `.gridmap(.gz)`, an occupancy image (`.png`, `.pgm`,
	 * `.bmp`, `.jpg`: black occupied, white free, with image_resolution and
	 * image_origin as pf-localization takes it), or a featloc-sim world file
	 * / wall list (its walls and obstacles). Relative: to the ini's folder.
	 * Empty: no map. */
	std::string map;
	/** The matcher class that matches scans against the map (empty: the
	 * [ScanMatcher] class); its parameters are its [ScanMatcher.<Class>]
	 * section's. PCM by default: against a map's virtual scans it has half
	 * ICP's error at a third of its time (doc/benchmarks.md). */
	std::string matcher_class = "featloc::PcmFeatureMatcher";
	/** The map matcher's correlative coarse search (its section's
	 * `coarse_search` is for the scan-to-scan matches). Off by default: a
	 * map match starts from the tracked pose, and a robot whose pose is
	 * lost is the global search's (MapLocalizer); with it on, the office's
	 * map matches take five times longer and its largest error grows
	 * (doc/benchmarks.md, "The search on by default"). */
	bool map_coarse_search = false;
	/** The map matcher's guess gate (`guess_gate_chi2` of its section, and
	 * its fallback's). Off by default: the EKF gates every map match
	 * against the same prediction (gate_chi2), with the map's own error
	 * added; the matcher's gate, without it, rejected office map matches
	 * that one took, declared lost a robot whose estimate was right, and
	 * each rejection cost a correlative search (doc/benchmarks.md, "Issue
	 * 15, twelfth session"). */
	bool map_guess_gate = false;
	/** [m] cell size of the grid a simplemap or a world file is drawn into
	 * (gridmaps and images keep their own). */
	double grid_resolution = 0.02;
	/** [m] size of one pixel of an occupancy image. */
	double image_resolution = 0.05;
	/** [px px] the image pixel at the map's origin (x from the left, y from
	 * the bottom, as MRPT's COccupancyGridMap2D::loadFromBitmapFile); empty:
	 * the image's centre. */
	std::vector<double> image_origin;
	/** A map match whose Mahalanobis^2 against the predicted pose exceeds
	 * this is not used (99.99%, 3 dof). */
	double gate_chi2 = 21.1;
	/** The map match's covariance times this before fusion (a map is not a
	 * scan: its own errors, a grid's cells, are not in the matcher's
	 * covariance). */
	double covariance_scale = 1.0;
	/** [m] the map's own error (its cells, a simplemap's pose errors), added
	 * in quadrature to the map match's x and y sigma before fusion. */
	double map_sigma_xy = 0.01;
	/** [rad] (degrees in the file) the same for yaw. */
	double map_sigma_yaw = 0.2 * 3.14159265358979323846 / 180.0;

	/** Global localization (`[Pipeline] initial_pose = global`, or once
	 * lost; MapLocalizer): the search's table cell [m]. */
	double global_resolution = 0.05;
	/** The robot is found at a hypothesis that scored at least
	 * global_min_score (share of the scan's points on the map) on each of
	 * its last global_confirm_scans scans... */
	unsigned int global_confirm_scans = 3;
	double global_min_score = 0.5;
	/** ...and whose scores over the search's scans exceed every other
	 * hypothesis's by this in total (a sum of shares of points). */
	double global_min_evidence = 0.2;
	/** ...or, with the same last scans, whose log-likelihood over the
	 * search's scans (each valid beam log(0.1 + 0.9 hit), a beam through
	 * the map log(0.01): MapLocalizer::Placement) exceeds every other
	 * hypothesis's by this [nats]. A few points that fit one room within
	 * centimetres and miss the other by decimetres (a desk moved, a door
	 * set elsewhere) are decisive here, while the share of points above
	 * moves by a few percent a scan. 0: off. */
	double global_min_log_evidence = 50;
	/** Each hypothesis's score on a scan is less the share of the scan's
	 * beams that pass through the map there
	 * (LocalizationMap::shareSeenThrough); false: the end points' score
	 * alone. */
	bool global_see_through = true;
	/** Tracking is lost after this many scans in a row without a usable
	 * map match (failed or rejected by the gate); 0: never. */
	unsigned int lost_after_scans = 5;

	bool enabled() const { return !map.empty(); }

	void loadFromConfigFile(
		const mrpt::config::CConfigFileBase& c, const std::string& s) override;
	void saveToConfigFile(
		mrpt::config::CConfigFileBase& c, const std::string& s) const override;
};
}  // namespace featloc
