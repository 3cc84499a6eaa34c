#include "featloc/pipeline/Pipeline.h"

#include <mrpt/core/bits_math.h>

#include <chrono>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "featloc/core/InputError.h"
#include "featloc/estimators/StereoStepResult.h"
#include "featloc/odometry/OdometrySamplingOffset.h"
#include "featloc/pipeline/StepAssembler.h"
#include "featloc/pipeline/StereoImagesHandler.h"

namespace featloc
{
namespace
{
constexpr size_t kMaxFailureExamples = 10;

void copyAssemblerStats(const StepAssembler& a, RunStats& s)
{
	s.laserLabel = a.selector().label();
	s.scansPerLabel = a.selector().scansPerLabel();
	s.invalidatedBeams = a.selector().invalidatedBeams();
	s.odometryReadings = a.odometryReadings();
	s.odometryActions = a.odometryActions();
	s.stepsWithoutOdometry = a.stepsWithoutOdometry();
	s.stepsWithExtrapolatedOdometry = a.stepsWithExtrapolatedOdometry();
	s.landmarkObservations = a.landmarkObservations();
	s.ignoredObservations = a.ignoredObservations();
}

void countStereo(const StereoStepResult& r, RunStats& s)
{
	s.stereoFrames++;
	s.stereoMap = r.map;
	bool wallInView = false;
	for (const auto& p : r.frame.planes) wallInView = wallInView || p.uMax >= p.uMin;
	if (!wallInView) s.stereoFramesWithoutWall++;
	s.stereoObservations += r.frame.observations.size();
	for (const auto& f : r.frame.features) s.stereoSelected += f.selected ? 1 : 0;
	s.stereoLandmarksStarted += r.update.added;
	s.stereoUpdates += r.update.used;
	s.stereoWallsObserved += r.update.wallsObserved;
	s.stereoWallsUsed += r.update.wallsUsed;
	s.stereoWallsRejected += r.update.wallsRejected;
	s.stereoTimes.push_back(r.frame.seconds);
}

/** "scan 12 (entry #25)": where a step's message applies. */
std::string scanAndEntry(const EstimationStep& step)
{
	return "scan " + std::to_string(step.scanIndex) + " (entry #" + std::to_string(step.entryIndex) + ")";
}

/** "5 CObservationBearingRange, 3 CObservationImage": what the log holds. */
std::string describeContents(const std::map<std::string, size_t>& perClass)
{
	std::string out;
	for (const auto& [cls, n] : perClass)
		out += (out.empty() ? "" : ", ") + std::to_string(n) + " " + cls;
	return out.empty() ? "no observations" : out;
}
}  // namespace

Pipeline::Pipeline(
	InputOptions input, OdometryOptions odometry, PipelineOptions options,
	PoseEstimator::Ptr estimator, ScanMatcher::Ptr matcher)
	: m_input(std::move(input)),
	  m_odometry(std::move(odometry)),
	  m_options(std::move(options)),
	  m_estimator(std::move(estimator)),
	  m_matcher(std::move(matcher)),
	  m_odometryCheck(m_odometry.covariance_check_window, m_odometry.covariance_check_quantile),
	  m_velocityPrior(m_odometry.no_odometry_velocity_window)
{
	if (!m_estimator) throw std::invalid_argument("Pipeline: no estimator");
	if (m_estimator->usesScanMatcher() && !m_matcher)
		throw std::invalid_argument(
			"Pipeline: estimator '" + m_estimator->name() +
			"' needs a scan matcher");
}

void Pipeline::setMapLocalizer(std::shared_ptr<MapLocalizer> localizer)
{
	if (localizer && !m_estimator->fusesAbsolutePoses())
		throw std::invalid_argument(
			"Pipeline: estimator '" + m_estimator->name() + "' cannot fuse poses in a map");
	m_mapLocalizer = std::move(localizer);
}

RunStats Pipeline::run(
	EntrySource& source, const std::vector<RunOutput*>& outputs, ProgressBar* progress,
	const std::atomic<bool>* stop)
{
	const std::string rawlogPath = source.name();
	const auto t0 = std::chrono::steady_clock::now();
	RunStats stats;
	stats.rawlog = rawlogPath;
	stats.estimator = m_estimator->name();
	if (m_estimator->usesScanMatcher()) stats.matcherClass = m_matcher->className();
	if (m_mapLocalizer)
	{
		stats.localizationMap = m_mapLocalizer->map().describe();
		stats.localizationMapFile = m_mapLocalizer->map().path();
	}
	stats.globalStart = m_options.global_start;
	m_keyframeScan.reset();
	m_previousMatchFailed = false;
	m_odometryCheck = OdometryCovarianceCheck(
		m_odometry.covariance_check_window, m_odometry.covariance_check_quantile);
	m_velocityPrior = ConstantVelocityPrior(m_odometry.no_odometry_velocity_window);

	std::unique_ptr<StepAssembler> assembler;
	const StereoImagesHandler* stereo = nullptr;  // owned by the assembler
	auto elapsed = [&] {
		return std::chrono::duration<double>(
				   std::chrono::steady_clock::now() - t0)
			.count();
	};
	try
	{
		assembler = std::make_unique<StepAssembler>(
			m_input, m_odometry, rawlogPath);
		auto stereoHandler = std::make_unique<StereoImagesHandler>(source.imagesDirectory());
		stereo = stereoHandler.get();
		assembler->addHandler(std::move(stereoHandler));
		RawlogEntry entry;
		std::vector<StepSource> used;
		std::vector<EstimationStep> ready;
		while (!assembler->full())
		{
			if (stop && stop->load())
			{
				stats.interrupted = true;
				break;
			}
			if (!source.next(entry)) break;
			stats.entries++;
			used.clear();
			ready.clear();
			assembler->push(entry, used, ready);
			for (auto* o : outputs) o->onEntry(entry, used);
			for (const auto& step : ready) processStep(step, outputs, stats);
			if (progress) progress->update(source.progress(), stats.steps);
		}
		ready.clear();
		assembler->finish(ready);
		for (const auto& step : ready) processStep(step, outputs, stats);
		if (progress) progress->done(stats.steps);
		copyAssemblerStats(*assembler, stats);
		stats.stereoPairs = stereo->pairs();

		if (stats.steps == 0 && !stats.interrupted)
		{
			std::ostringstream msg;
			msg << "rawlog '" << rawlogPath << "' (" << stats.entries
				<< " entries) has nothing featloc can use: no 2-D laser scan";
			if (!m_input.laser_label.empty())
				msg << " with sensor label '" << m_input.laser_label << "'";
			msg << " and no range-bearing observation (it holds "
				<< describeContents(assembler->objectsPerClass());
			if (!stats.scansPerLabel.empty())
			{
				msg << "; 2-D scans per label:";
				for (const auto& [label, n] : stats.scansPerLabel)
					msg << " '" << label << "': " << n;
			}
			msg << ")";
			throw InputError(msg.str());
		}
		if (stats.stereoFrames > 0 && stats.stereoFramesWithoutWall == stats.stereoFrames)
			throw InputError(
				"no wall of the stereo landmarks' map '" + stats.stereoMap + "' was in view in any of the " +
				std::to_string(stats.stereoFrames) +
				" stereo pairs (from the estimated poses): the map does not cover what the camera saw "
				"(another building, or the map's frame differs from the run's [Pipeline] initial pose)");
		stats.wallTime = elapsed();
		for (auto* o : outputs) o->finish(stats);
	}
	catch (const std::exception& e)
	{
		if (progress) progress->done(stats.steps);
		if (assembler) copyAssemblerStats(*assembler, stats);
		if (stereo) stats.stereoPairs = stereo->pairs();
		stats.ok = false;
		stats.error = e.what();
		stats.wallTime = elapsed();
		// Keep what was produced: every output completes its file.
		for (auto* o : outputs)
		{
			try
			{
				o->finish(stats);
			}
			catch (...)
			{
			}
		}
		throw;
	}
	return stats;
}

mrpt::poses::CPose2D Pipeline::actionStep(const EstimationStep& step)
{
	// Read at the scan's instant (or interpolated there): no offset.
	return step.odometryReadOffScan() ? step.odometry.mean : mrpt::poses::CPose2D();
}

bool Pipeline::isNewKeyframe(const MatchResult* match) const
{
	if (m_options.keyframe_distance <= 0 && m_options.keyframe_angle <= 0)
		return true;
	// The raw match's motion decides even when the EKF gated the match out:
	// counting a gated match as failed (new keyframe), or using the
	// estimate's motion instead, were both measured worse on most logs
	// (doc/benchmarks.md, "Keyframe decision after a gated match").
	const bool failed = match && !match->success;
	if (failed && !m_options.failed_match_keeps_keyframe) return true;
	// Without a match (the odometry estimator) or after a failed one, the
	// estimate's own motion since the keyframe decides: otherwise every
	// scan would be a keyframe, and map.simplemap would hold the whole log.
	const mrpt::poses::CPose2D m = match && match->success
		? match->estimate.mean
		: m_estimator->pose().mean - m_estimator->currentKeyframePose().value_or(m_keyframePose);
	// After a failure that follows a good match: further, so the next good
	// match still measures the failed step (failed_match_keyframe_factor).
	// In a streak of failures the reference is what fails: as usual.
	const double factor =
		failed && !m_previousMatchFailed ? m_options.failed_match_keyframe_factor : 1.0;
	return (m_options.keyframe_distance > 0 && m.norm() >= factor * m_options.keyframe_distance) ||
		(m_options.keyframe_angle > 0 && std::abs(m.phi()) >= factor * m_options.keyframe_angle);
}

void Pipeline::processStep(
	const EstimationStep& logStep, const std::vector<RunOutput*>& outputs, RunStats& stats)
{
	// The step as the estimator sees it: the odometry covariance times the
	// check's factor (1 while the log's covariance agrees with the matches).
	// A step without odometry moves as the estimate has lately (its
	// covariance stays the no_odometry_* prior's).
	EstimationStep step = logStep;
	if (!logStep.hasOdometry && logStep.index > 0 &&
		m_odometry.no_odometry_prior == "constant_velocity")
		if (const auto motion = m_velocityPrior.motionTo(logStep.time))
		{
			step.odometry.mean = *motion;
			stats.stepsWithVelocityPrior++;
		}
	const mrpt::poses::CPosePDFGaussian unscaledOdometry = step.odometry;
	step.odometry.cov *= m_odometryCheck.scale();
	if (m_odometry.action_sampling_offset && step.odometryReadOffScan())
		step.odometrySamplingCovariance = OdometrySamplingOffset::ofReading(step.odometry.mean);
	MatchResult match;
	const MatchResult* matchPtr = nullptr;
	bool usedMatch = false;
	std::string fallbackReason;	 // why the estimator did not use a good match
	if (step.index == 0)
		m_estimator->start(m_options.initialPose(), step);
	else
	{
		m_odometrySinceKeyframe += unscaledOdometry;
		if (m_estimator->usesScanMatcher() && step.scan && m_keyframeScan)
		{
			match = matchToKeyframe(step);
			matchPtr = &match;
			stats.matchesAttempted++;
			stats.matchTimes.push_back(match.timeSeconds);
			stats.matchIterations.push_back(match.iterations);
			if (match.ambiguous) stats.ambiguousMatches++;
			if (!match.guessGateOverruled.empty()) stats.guessGateOverruled++;
			if (!match.matcherFallback.empty()) stats.matcherFallbacks++;
			if (match.segmentsDroppedByResiduals > 0)
			{
				stats.matchesWithSegmentsDroppedByResiduals++;
				stats.segmentsDroppedByResiduals += match.segmentsDroppedByResiduals;
			}
			if (match.confirmedShare > 0) stats.coarseSearchSkipped++;
			if (match.confirmationSlid) stats.coarseConfirmationsSlid++;
			if (match.rangeLatticeStep > 0)
			{
				stats.rangeLatticeMatches++;
				stats.rangeLatticeSteps.push_back(match.rangeLatticeStep);
				if (match.rangesDequantized) stats.dequantizedMatches++;
			}
			if (match.guessKeptAlongFreeDirection) stats.guessKeptAlongFreeDirection++;
			if (!match.primaryFailure.empty())
			{
				stats.fallbackMatcherMatches++;
				if (match.success) stats.fallbackMatcherSuccesses++;
			}
			if (!match.success)
			{
				stats.matchFailures++;
				stats.matchFailuresByKind[match.failureKind]++;
				if (stats.failureExamples.size() < kMaxFailureExamples)
					stats.failureExamples.push_back(
						scanAndEntry(step) + ": " + match.failureReason);
			}
		}
		const auto e0 = std::chrono::steady_clock::now();
		usedMatch = m_estimator->process(step, matchPtr);
		stats.estimatorTimes.push_back(
			std::chrono::duration<double>(std::chrono::steady_clock::now() - e0).count());
		if (matchPtr && !usedMatch)
		{
			stats.fallbacks++;
			if (match.success) fallbackReason = m_estimator->lastFallbackReason();
			if (match.success && stats.rejectionExamples.size() < kMaxFailureExamples)
				stats.rejectionExamples.push_back(scanAndEntry(step) + ": " + fallbackReason);
		}
	}
	MapLocalizer::Outcome inMap;
	if (m_mapLocalizer)
	{
		inMap = localizeInMap(step, stats);
		if (inMap.event == "found")	 // the estimator restarted
		{
			m_keyframeScan.reset();
			m_previousMatchFailed = false;
			m_velocityPrior.clear();
		}
	}
	const bool keyframe = step.scan && (!m_keyframeScan || isNewKeyframe(matchPtr));
	if (matchPtr) m_previousMatchFailed = !matchPtr->success;
	if (keyframe)
	{
		m_keyframeScan = step.scan;
		m_keyframePose = m_estimator->pose().mean;
		m_odometrySinceKeyframe = mrpt::poses::CPosePDFGaussian();
		m_keyframeActionStep = actionStep(logStep);
		m_estimator->markKeyframe();
		stats.keyframes++;
	}
	stats.steps++;
	if (step.scan) stats.scans++;
	stats.odometryCovarianceScale = m_odometryCheck.maxScale();
	if (const auto b = m_estimator->odometryDirectionOffset())
		stats.odometryDirectionOffsetDeg =
			std::make_pair(mrpt::RAD2DEG(b->first), mrpt::RAD2DEG(b->second));
	if (stats.steps == 1) m_firstStepTime = step.time;
	m_velocityPrior.add(step.time, m_estimator->pose().mean);
	stats.logSeconds = std::chrono::duration<double>(step.time - m_firstStepTime).count();
	const std::vector<EstimatedLandmark> landmarks = m_estimator->landmarks();
	stats.landmarksInMap = landmarks.size();
	const StereoStepResult* stereo = m_estimator->lastStereo();
	if (stereo) countStereo(*stereo, stats);
	const StepRecord record{step, m_estimator->pose(), matchPtr, usedMatch, &landmarks, stereo,
		fallbackReason, keyframe, inMap.mapMatch ? &inMap.mapMatch->match : nullptr, inMap.used,
		inMap.reason};
	for (auto* o : outputs) o->onStep(record);
}

MapLocalizer::Outcome Pipeline::localizeInMap(const EstimationStep& step, RunStats& stats)
{
	MapLocalizer::Outcome out = m_mapLocalizer->process(step, *m_estimator);
	if (out.global)
	{
		stats.globalSearches++;
		stats.globalSearchTimes.push_back(out.global->seconds);
	}
	if (out.event == "found" && stats.firstFoundTime < 0)
		stats.firstFoundTime = mrpt::Clock::toDouble(step.time);
	if (!out.event.empty())
		stats.localizationEvents.push_back(out.event + " at " + scanAndEntry(step) + ": " + out.message);
	if (!out.mapMatch) return out;
	const auto& r = *out.mapMatch;
	stats.mapMatchesAttempted++;
	stats.mapMatchTimes.push_back(r.match.timeSeconds);
	if (!r.match.success)
	{
		stats.mapMatchFailures++;
		stats.mapMatchFailuresByKind[r.match.failureKind]++;
	}
	else if (out.used)
		stats.mapMatchesUsed++;
	else
	{
		stats.mapMatchesRejected++;
		if (stats.mapRejectionExamples.size() < kMaxFailureExamples)
			stats.mapRejectionExamples.push_back(scanAndEntry(step) + ": " + out.reason);
	}
	return out;
}

MatchResult Pipeline::matchToKeyframe(const EstimationStep& step)
{
	// Guess: previous estimate (+) odometry, relative to the keyframe.
	mrpt::poses::CPosePDFGaussian guess = m_odometrySinceKeyframe;
	guess.cov *= m_odometryCheck.scale();
	guess.mean = (m_estimator->pose().mean + step.odometry.mean) -
		m_estimator->currentKeyframePose().value_or(m_keyframePose);
	mrpt::math::CMatrixDouble33 allowance;
	if (m_odometry.action_sampling_offset)
		allowance = OdometrySamplingOffset::covariance(
			m_keyframeActionStep, actionStep(step), guess.mean);
	MatchResult match = m_matcher->match(*m_keyframeScan, *step.scan, guess, allowance);
	if (m_odometry.covariance_check && (match.success || match.rejectedByGuessGate))
	{
		// What the allowance explains is not the covariance's fault.
		mrpt::poses::CPosePDFGaussian m = match.estimate;
		m.cov += allowance;
		m_odometryCheck.observe(m_odometrySinceKeyframe, m);
	}
	return match;
}
}  // namespace featloc
