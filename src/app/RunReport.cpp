#include "featloc/app/RunReport.h"
#include "featloc/core/WholeFile.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <stdexcept>

#include "featloc/app/RunConfiguration.h"
#include "featloc/config/TrackedConfig.h"
#include "featloc/core/InputError.h"
#include "featloc/eval/ErrorStats.h"
#include "featloc/eval/TrajectoryEvaluator.h"
#include "featloc/eval/TrajectoryPlot.h"
#include "featloc/localization/MapLocalizer.h"
#include "featloc/output/ResultsFolder.h"
#include "featloc/output/SummaryJsonWriter.h"

namespace featloc
{
RunReport::Reference RunReport::readGroundTruth(const TrackedConfig& cfg, const RunConfiguration& rc)
{
	const std::string path = cfg.resolvePath(
		EvaluationOptions::kSection, "ground_truth", rc.evaluation.ground_truth);
	TrajectoryFile::Format format = TrajectoryFile::Format::Auto;
	Reference r;
	try
	{
		r.trajectory = TrajectoryFile::read(path, format, &format);
	}
	catch (const InputError& e)
	{
		throw InputError(std::string("[Evaluation] ground_truth: ") + e.what());
	}
	r.description = path + " (" + TrajectoryFile::formatDescription(format) + ")";
	return r;
}

void RunReport::writeUsedConfig(const TrackedConfig& cfg, const std::string& path)
{
	// The run's own path keys, whether or not the run has resolved them yet
	// (the plugins resolve theirs when they load).
	for (const auto& [section, key] : {std::make_pair(InputOptions::kSection, "rawlog"),
			 std::make_pair(OutputOptions::kSection, "dir"),
			 std::make_pair(EvaluationOptions::kSection, "ground_truth")})
		cfg.resolvePath(section, key, cfg.read_string(section, key, ""));
	writeWholeFile(path, [&](const std::string& file) {
		std::ofstream f(file);
		f << "# effective configuration of this run (ini + --set); relative paths made absolute\n"
		  << cfg.contentWithResolvedPaths();
		f.close();
		if (!f) throw std::runtime_error("cannot write '" + path + "'");
	});
}

void RunReport::printAbandoned(const ResultsFolder& folder)
{
	for (const auto& a : folder.abandoned())
		std::printf(
			"  note: a run killed before it finished left its partial results in %s "
			"(kept; delete it when done)\n",
			a.c_str());
}

void RunReport::printSummary(const RunStats& s)
{
	std::printf(
		"%s %zu steps (%zu with a scan) from %zu entries",
		s.interrupted ? "interrupted after" : "processed", s.steps, s.scans, s.entries);
	if (s.invalidatedBeams) std::printf(" (%zu beams invalidated)", s.invalidatedBeams);
	std::printf("\n");
	// "N s of log in M s": the whole run, matcher and I/O included.
	if (s.logSeconds > 0 && s.wallTime > 0)
		std::printf(
			"  %.1f s of log in %.2f s (%.1fx real time, everything included)\n",
			s.logSeconds, s.wallTime, s.logSeconds / s.wallTime);
	if (s.stepsWithoutOdometry)
		std::printf("  %zu steps had no odometry (%zu moved at the estimate's recent velocity, "
					"the others not at all: [Odometry] no_odometry_prior)\n",
			s.stepsWithoutOdometry, s.stepsWithVelocityPrior);
	if (s.stepsWithExtrapolatedOdometry)
		std::printf("  %zu steps extrapolated the odometry past its newest reading "
					"([Odometry] max_extrapolation)\n",
			s.stepsWithExtrapolatedOdometry);
	if (s.odometryCovarianceScale > 1)
		std::printf(
			"  odometry covariance: the log's is too small for the motion the matches "
			"show; inflated x%.1f (see [Odometry] covariance_check)\n",
			s.odometryCovarianceScale);
	if (s.odometryDirectionOffsetDeg)
		std::printf(
			"  odometry direction offset learnt by the EKF: %.2f +- %.2f deg (the odometry's "
			"direction of travel against the scanner's; [Ekf] odometry_direction_sigma_DEG)\n",
			s.odometryDirectionOffsetDeg->first, s.odometryDirectionOffsetDeg->second);
	for (const auto& [cls, n] : s.ignoredObservations)
		std::printf("  %zu %s ignored (nothing in featloc uses them)\n", n, cls.c_str());
	if (s.landmarkObservations || s.landmarksInMap)
		std::printf(
			"  %zu range-bearing observations; %zu landmarks in the map at the end\n",
			s.landmarkObservations, s.landmarksInMap);
	if (s.stereoFrames)
	{
		const ErrorStats st = ErrorStats::of(s.stereoTimes);
		std::printf(
			"  %zu stereo pairs: %zu segments on map walls, %zu selected; %zu landmarks started, "
			"%zu observations used; %.1f ms per pair (median)\n",
			s.stereoFrames, s.stereoObservations, s.stereoSelected, s.stereoLandmarksStarted, s.stereoUpdates,
			st.median * 1e3);
		if (s.stereoWallsObserved)
			std::printf("    %zu wall observations (stereo_walls.txt): %zu used, %zu failed their gate\n",
				s.stereoWallsObserved, s.stereoWallsUsed, s.stereoWallsRejected);
		if (s.stereoFramesWithoutWall)
			std::printf("    %zu pairs saw no wall of the map '%s'\n", s.stereoFramesWithoutWall, s.stereoMap.c_str());
	}
	if (s.matchesAttempted)
	{
		const ErrorStats t = ErrorStats::of(s.matchTimes);
		std::printf(
			"  %zu matches: %zu failed (%zu fell back to odometry); time per "
			"match mean %.2f ms, median %.2f ms, p95 %.2f ms\n",
			s.matchesAttempted, s.matchFailures, s.fallbacks, t.mean * 1e3, t.median * 1e3,
			t.p95 * 1e3);
		if (s.fallbackMatcherMatches)
			std::printf("    %zu made by the fallback matcher after %s failed, was ambiguous or weak (%zu of them succeeded; "
						"fallback_class)\n",
				s.fallbackMatcherMatches, s.matcherClass.c_str(), s.fallbackMatcherSuccesses);
		if (s.rangeLatticeMatches)
			std::printf("    %zu with the current scan's ranges on a lattice of %.3f m (median; "
						"RangeLattice): %zu of them put back on their surfaces (dequantize_ranges)\n",
				s.rangeLatticeMatches, ErrorStats::of(s.rangeLatticeSteps).median,
				s.dequantizedMatches);
		if (s.coarseSearchSkipped)
			std::printf("    %zu without the coarse search: the points confirmed the iterations from "
						"the guess (coarse_confirm_share)\n",
				s.coarseSearchSkipped);
		if (s.coarseConfirmationsSlid)
			std::printf("    %zu with the coarse search after all: the points confirmed the "
						"iterations from the guess, but a pose slid along its least certain "
						"direction as well (coarse_confirm_probe)\n",
				s.coarseConfirmationsSlid);
		if (s.guessKeptAlongFreeDirection)
			std::printf("    %zu kept the guess along the one direction their points left free, as "
						"along a corridor (free_direction_from_guess; used, flagged ambiguous)\n",
				s.guessKeptAlongFreeDirection);
		for (const auto& ex : s.failureExamples) std::printf("    failed: %s\n", ex.c_str());
		for (const auto& ex : s.rejectionExamples) std::printf("    not used: %s\n", ex.c_str());
	}
	if (!s.localizationMap.empty())
	{
		const ErrorStats t = ErrorStats::of(s.mapMatchTimes);
		std::printf(
			"  map %s:\n    %zu scans matched against it: %zu used, %zu failed, %zu rejected by "
			"the gate; %.2f ms per map match (median)\n",
			s.localizationMap.c_str(), s.mapMatchesAttempted, s.mapMatchesUsed, s.mapMatchFailures,
			s.mapMatchesRejected, t.median * 1e3);
		for (const auto& ex : s.mapRejectionExamples) std::printf("    not used: %s\n", ex.c_str());
		if (s.globalSearches)
			std::printf("    %zu global searches, %.2f s each (mean)\n", s.globalSearches,
				ErrorStats::of(s.globalSearchTimes).mean);
		for (const auto& ev : s.localizationEvents) std::printf("    %s\n", ev.c_str());
	}
	if (!s.estimatorTimes.empty())
	{
		const ErrorStats e = ErrorStats::of(s.estimatorTimes);
		std::printf(
			"  estimator %s: mean %.1f us per step (matcher excluded)\n", s.estimator.c_str(),
			e.mean * 1e6);
	}
}

/** The evaluation against the reference (summary.json, nees.txt) and
 * trajectory.png, with or without a reference. */
void RunReport::evaluateAndPlot(
	const RunConfiguration& rc, const std::optional<Reference>& reference,
	const ResultsFolder& folder, const RunStats& stats, SummaryJsonWriter& summary)
{
	if (stats.steps == 0) return;
	const std::vector<mrpt::math::TPoint2D> map =
		rc.mapLocalizer ? rc.mapLocalizer->map().occupiedCells() : std::vector<mrpt::math::TPoint2D>{};
	Trajectory est = TrajectoryFile::read(folder.stagedFile("poses_cov.txt"));
	est.source = folder.finalFile("poses_cov.txt");	// where the user will find it
	char title[160];
	if (!reference)
	{
		std::snprintf(title, sizeof(title), "%s: %zu poses (no ground truth)",
			stats.estimator.c_str(), est.poses.size());
		TrajectoryPlot::write(folder.stagedFile("trajectory.png"), Trajectory{}, est, {}, title, map);
		return;
	}
	if (stats.globalStart)
	{
		// Before the robot is found its estimate is not in the map's frame.
		const size_t all = est.poses.size();
		est.poses.erase(std::remove_if(est.poses.begin(), est.poses.end(),
							[&](const TimedPose& p) { return stats.firstFoundTime < 0 || p.t < stats.firstFoundTime; }),
			est.poses.end());
		std::printf("global localization: evaluated from the step where the robot was first found "
					"(%zu of %zu poses)\n",
			est.poses.size(), all);
		if (est.poses.size() < 2)
			throw InputError("the robot was never found in the map: nothing to evaluate");
	}
	const TrajectoryEvaluator evaluator(rc.evaluation.max_time_difference, rc.evaluation.align);
	const EvaluationReport rep = evaluator.evaluate(reference->trajectory, est);
	std::printf("against %s:\n%s", reference->description.c_str(), rep.toText().c_str());
	summary.writeWithEvaluation(stats, rep.toJson());
	if (rep.hasNees) rep.writeNeesSeries(folder.stagedFile("nees.txt"));
	std::snprintf(title, sizeof(title), "%s: ATE rmse %.3f m over %zu poses",
		stats.estimator.c_str(), rep.ate.rmse, rep.associated);
	TrajectoryPlot::write(
		folder.stagedFile("trajectory.png"), reference->trajectory, est, rep.alignment, title, map);
}

}  // namespace featloc
