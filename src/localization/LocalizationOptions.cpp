#include "featloc/localization/LocalizationOptions.h"

#include "featloc/config/ConfigValues.h"
#include "featloc/config/TrackedConfig.h"

namespace featloc
{
void LocalizationOptions::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	using namespace featloc::config;
	read(c, s, "map", map);
	read(c, s, "matcher_class", matcher_class);
	read(c, s, "map_coarse_search", map_coarse_search);
	read(c, s, "map_guess_gate", map_guess_gate);
	read(c, s, "grid_resolution", grid_resolution);
	read(c, s, "image_resolution", image_resolution);
	read(c, s, "image_origin", image_origin);
	read(c, s, "gate_chi2", gate_chi2);
	read(c, s, "covariance_scale", covariance_scale);
	read(c, s, "map_sigma_xy", map_sigma_xy);
	readDegrees(c, s, "map_sigma_yaw_DEG", map_sigma_yaw);
	read(c, s, "global_resolution", global_resolution);
	read(c, s, "global_confirm_scans", global_confirm_scans);
	read(c, s, "global_min_score", global_min_score);
	read(c, s, "global_min_evidence", global_min_evidence);
	read(c, s, "global_min_log_evidence", global_min_log_evidence);
	read(c, s, "global_see_through", global_see_through);
	read(c, s, "lost_after_scans", lost_after_scans);
	require(global_resolution >= 0.01 && global_resolution <= 0.5, c, s, "global_resolution",
		"in [0.01, 0.5] [m]");
	require(global_confirm_scans >= 1, c, s, "global_confirm_scans", ">= 1");
	require(global_min_score > 0 && global_min_score <= 1, c, s, "global_min_score", "in (0, 1]");
	require(global_min_evidence > 0, c, s, "global_min_evidence", "> 0");
	require(global_min_log_evidence >= 0, c, s, "global_min_log_evidence", ">= 0 (0: off)");
	require(grid_resolution > 0.001 && grid_resolution <= 1, c, s, "grid_resolution",
		"in (0.001, 1] [m]");
	require(image_resolution > 0.001 && image_resolution <= 10, c, s, "image_resolution",
		"in (0.001, 10] [m/pixel]");
	require(image_origin.empty() || image_origin.size() == 2, c, s, "image_origin",
		"empty (the image's centre) or [px py]");
	require(gate_chi2 > 0, c, s, "gate_chi2", "> 0");
	require(covariance_scale > 0, c, s, "covariance_scale", "> 0");
	require(map_sigma_xy >= 0, c, s, "map_sigma_xy", ">= 0 [m]");
	require(map_sigma_yaw >= 0, c, s, "map_sigma_yaw_DEG", ">= 0 [deg]");
	if (!map.empty())
		if (const auto* tc = dynamic_cast<const TrackedConfig*>(&c)) map = tc->resolvePath(s, "map", map);
}

void LocalizationOptions::saveToConfigFile(
	mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	using namespace featloc::config;
	write(c, s, "map", map,
		"known map to localize in (empty: none): .simplemap(.gz), .gridmap(.gz), an occupancy "
		"image (.png/.pgm/.bmp/.jpg) or a featloc-sim world file; needs estimator = ekf");
	write(c, s, "matcher_class", matcher_class,
		"matcher of scans against the map (empty: the [ScanMatcher] class); parameters in "
		"[ScanMatcher.<Class>]");
	write(c, s, "map_coarse_search", map_coarse_search,
		"the map matcher's correlative coarse search (its section's coarse_search is for "
		"scan-to-scan matches)");
	write(c, s, "map_guess_gate", map_guess_gate,
		"the map matcher's guess gate (its section's guess_gate_chi2, and its fallback's); off: "
		"gate_chi2 gates the map match against the prediction");
	write(c, s, "grid_resolution", grid_resolution,
		"[m] cell of the grid a simplemap or world file is drawn into");
	write(c, s, "image_resolution", image_resolution, "[m/pixel] occupancy image");
	write(c, s, "image_origin", image_origin,
		"[px px] image pixel at the map origin (x from the left, y from the bottom); empty: centre");
	write(c, s, "gate_chi2", gate_chi2,
		"a map match whose Mahalanobis^2 against the prediction exceeds this is not used");
	write(c, s, "covariance_scale", covariance_scale, "the map match's covariance times this");
	write(c, s, "map_sigma_xy", map_sigma_xy, "[m] the map's own error, added in quadrature to the map match's x and y sigma");
	writeDegrees(c, s, "map_sigma_yaw_DEG", map_sigma_yaw,
		"[deg] the same for yaw");
	write(c, s, "global_resolution", global_resolution,
		"[m] global localization (initial_pose = global, or lost): the search's cell");
	write(c, s, "global_confirm_scans", global_confirm_scans,
		"global: found at a hypothesis whose last N scans (moved by odometry) each score...");
	write(c, s, "global_min_score", global_min_score,
		"global: ...at least this share of the scan on the map...");
	write(c, s, "global_min_evidence", global_min_evidence,
		"global: ...and whose scores over the search's scans exceed every other hypothesis's by this in total");
	write(c, s, "global_min_log_evidence", global_min_log_evidence,
		"global: or, with the same last N scans, whose log-likelihood over the search's scans exceeds every other hypothesis's by this [nats] (0: off)");
	write(c, s, "global_see_through", global_see_through,
		"global: a hypothesis's score on a scan is less the share of the scan's beams that pass through the map there (false: the end points alone)");
	write(c, s, "lost_after_scans", lost_after_scans,
		"tracking is lost after this many scans in a row without a usable map match (0: never)");
}
}  // namespace featloc
