#include "featloc/output/SummaryJsonWriter.h"
#include "featloc/core/WholeFile.h"

#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "featloc/eval/ErrorStats.h"

namespace featloc
{
namespace
{
nlohmann::json toJson(const RunStats& s, const std::vector<std::string>& outputs)
{
	nlohmann::json j;
	j["status"] = !s.ok ? "error" : (s.interrupted ? "interrupted" : "ok");
	if (!s.ok) j["error"] = s.error;
	j["rawlog"] = s.rawlog;
	j["estimator"] = s.estimator;
	j["matcher"] = s.matcherClass.empty() ? nlohmann::json() : nlohmann::json(s.matcherClass);
	j["laser_label"] = s.laserLabel;
	j["counts"] = {
		{"entries", s.entries},
		{"steps", s.steps},
		{"scans", s.scans},
		{"scans_per_label", s.scansPerLabel},
		{"stereo_pairs", s.stereoPairs},
		{"odometry_readings", s.odometryReadings},
		{"odometry_actions", s.odometryActions},
		{"steps_without_odometry", s.stepsWithoutOdometry},
		{"steps_with_extrapolated_odometry", s.stepsWithExtrapolatedOdometry},
		{"steps_with_constant_velocity_prior", s.stepsWithVelocityPrior},
		{"landmark_observations", s.landmarkObservations},
		{"landmarks_in_map", s.landmarksInMap},
		{"invalidated_beams", s.invalidatedBeams},
		{"keyframes", s.keyframes},
		{"matches", s.matchesAttempted},
		{"match_failures", s.matchFailures},
		{"match_failures_by_kind", s.matchFailuresByKind},
		{"ambiguous_matches_used", s.ambiguousMatches},
		{"guess_gate_overruled", s.guessGateOverruled},
		{"matcher_fallbacks", s.matcherFallbacks},
		{"matches_with_segments_dropped_by_residuals", s.matchesWithSegmentsDroppedByResiduals},
		{"segments_dropped_by_residuals", s.segmentsDroppedByResiduals},
		{"fallback_matcher_matches", s.fallbackMatcherMatches},
		{"fallback_matcher_successes", s.fallbackMatcherSuccesses},
		{"coarse_search_skipped", s.coarseSearchSkipped},
		{"coarse_confirmations_slid", s.coarseConfirmationsSlid},
		{"range_lattice_matches", s.rangeLatticeMatches},
		{"range_lattice_step_m",
			s.rangeLatticeSteps.empty() ? 0.0 : ErrorStats::of(s.rangeLatticeSteps).median},
		{"dequantized_matches", s.dequantizedMatches},
		{"guess_kept_along_free_direction", s.guessKeptAlongFreeDirection},
		{"fallbacks_to_odometry", s.fallbacks},
		{"ignored_observations", s.ignoredObservations}};
	if (s.stereoFrames)
	{
		const ErrorStats st = ErrorStats::of(s.stereoTimes);
		j["stereo_landmarks"] = {
			{"map", s.stereoMap},
			{"pairs_processed", s.stereoFrames},
			{"pairs_without_wall_in_view", s.stereoFramesWithoutWall},
			{"observations_on_planes", s.stereoObservations},
			{"features_selected", s.stereoSelected},
			{"landmarks_started", s.stereoLandmarksStarted},
			{"observations_used", s.stereoUpdates},
			{"wall_observations", s.stereoWallsObserved},
			{"wall_observations_used", s.stereoWallsUsed},
			{"wall_observations_failed_gate", s.stereoWallsRejected},
			{"time_per_pair_s", {{"mean", st.mean}, {"median", st.median}, {"p95", st.p95}, {"max", st.max}}}};
	}
	if (!s.localizationMap.empty())
	{
		const ErrorStats mt = ErrorStats::of(s.mapMatchTimes);
		j["localization"] = {
			{"map", s.localizationMap},
			{"map_file", s.localizationMapFile},
			{"map_matches", s.mapMatchesAttempted},
			{"map_matches_used", s.mapMatchesUsed},
			{"map_match_failures", s.mapMatchFailures},
			{"map_match_failures_by_kind", s.mapMatchFailuresByKind},
			{"map_matches_rejected_by_gate", s.mapMatchesRejected},
			{"rejection_examples", s.mapRejectionExamples},
			{"events", s.localizationEvents},
			{"global_searches", s.globalSearches},
			{"time_per_global_search_s", ErrorStats::of(s.globalSearchTimes).mean},
			{"time_per_map_match_s", {{"mean", mt.mean}, {"median", mt.median}, {"p95", mt.p95}, {"max", mt.max}}}};
	}
	j["failure_examples"] = s.failureExamples;
	j["rejection_examples"] = s.rejectionExamples;
	const ErrorStats t = ErrorStats::of(s.matchTimes);
	j["match_time_s"] = {
		{"count", t.count}, {"mean", t.mean}, {"median", t.median},
		{"p95", t.p95},		{"max", t.max}};
	std::vector<double> its(s.matchIterations.begin(), s.matchIterations.end());
	const ErrorStats it = ErrorStats::of(its);
	j["match_iterations"] = {
		{"mean", it.mean}, {"median", it.median}, {"max", it.max}};
	const ErrorStats e = ErrorStats::of(s.estimatorTimes);
	j["estimator_time_s"] = {
		{"count", e.count}, {"mean", e.mean}, {"median", e.median},
		{"p95", e.p95},		{"max", e.max}};
	j["wall_time_s"] = s.wallTime;
	j["log_duration_s"] = s.logSeconds;
	j["real_time_factor"] = s.wallTime > 0 ? s.logSeconds / s.wallTime : 0.0;
	j["odometry_covariance_scale"] = s.odometryCovarianceScale;
	if (s.odometryDirectionOffsetDeg)
		j["odometry_direction_offset_deg"] = {{"estimate", s.odometryDirectionOffsetDeg->first},
			{"sigma", s.odometryDirectionOffsetDeg->second}};
	else
		j["odometry_direction_offset_deg"] = nullptr;
	j["outputs"] = outputs;
	return j;
}

void writeJson(const std::string& path, const nlohmann::json& j)
{
	writeWholeFile(path, [&](const std::string& file) {
		std::ofstream out(file);
		if (!out) throw std::runtime_error("cannot write '" + path + "'");
		// MRPT's exception texts can quote raw bytes of a damaged file:
		// replace invalid UTF-8 rather than lose the whole summary.
		out << j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
		out.close();
		if (!out) throw std::runtime_error("error writing '" + path + "'");
	});
}
}  // namespace

SummaryJsonWriter::SummaryJsonWriter(
	std::string path, std::vector<std::string> outputs)
	: m_path(std::move(path)), m_outputs(std::move(outputs))
{
}

void SummaryJsonWriter::finish(const RunStats& stats)
{
	auto j = toJson(stats, m_outputs);
	for (const auto& [key, text] : m_members) j[key] = nlohmann::json::parse(text);
	writeJson(m_path, j);
}

void SummaryJsonWriter::addMember(const std::string& key, const std::string& json)
{
	m_members.emplace_back(key, json);
}

void SummaryJsonWriter::writeWithEvaluation(
	const RunStats& stats, const std::string& evaluationJson)
{
	addMember("evaluation", evaluationJson);
	finish(stats);
}
}  // namespace featloc
