#include "featloc/eval/ScanPairBenchmark.h"

#include <mrpt/core/bits_math.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/random/RandomGenerators.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

#include "featloc/eval/EvaluationReport.h"
#include "featloc/eval/ErrorStats.h"
#include "featloc/math/DiagonalPoseGaussian.h"
#include "featloc/math/PoseDifference.h"
#include "featloc/scan/ScanPoints.h"

namespace featloc
{
std::vector<ScanPairBenchmark::Result> ScanPairBenchmark::run(
	const std::vector<ScanPairSample>& pairs,
	const std::vector<ScanMatcher::Ptr>& matchers, const Options& o, const Progress& progress)
{
	mrpt::random::CRandomGenerator rng(o.seed);
	const bool uniform = o.perturbation == "uniform";
	// The guess's standard deviations: those of the perturbation (a uniform
	// draw in [-a, a] has sigma a / sqrt(3)).
	const double sigmaScale = uniform ? 1.0 / std::sqrt(3.0) : 1.0;
	const double sigmaXY = o.perturbXY * sigmaScale, sigmaYaw = o.perturbYaw * sigmaScale;

	struct Acc
	{
		std::vector<double> ex, ey, ew, et, time, nees;
		double boundedTrans = 0, boundedYaw = 0, boundTrans = 0, boundYaw = 0;
		double iterations = 0;
	};
	std::vector<Acc> acc(matchers.size());
	std::vector<Result> res(matchers.size());
	for (size_t m = 0; m < matchers.size(); m++) res[m].matcher = matchers[m]->className();

	for (size_t k = 0; k < pairs.size(); k++)
	{
		const auto& p = pairs[k];
		auto draw = [&](double a) {
			return uniform ? rng.drawUniform(-a, a) : a * rng.drawGaussian1D_normalized();
		};
		const double dx = draw(o.perturbXY), dy = draw(o.perturbXY), dw = draw(o.perturbYaw);
		mrpt::poses::CPosePDFGaussian guess;
		mrpt::poses::CPose2D truth = p.truth;
		const mrpt::obs::CObservation2DRangeScan* current = p.current.get();
		mrpt::obs::CObservation2DRangeScan moved;
		if (o.applyMotion)
		{
			// Nunez et al.'s protocol: the current scan is moved by a random
			// motion M (mean appliedMotion, the draw as its spread): its
			// points, in its new robot frame, are M^-1 (+) the old ones, so
			// the true motion becomes truth (+) M; the guess is the mean.
			const mrpt::poses::CPose2D M(o.appliedMotion.x() + dx, o.appliedMotion.y() + dy,
				o.appliedMotion.phi() + dw);
			moved = *p.current;
			moved.sensorPose = mrpt::poses::CPose3D(-M) + p.current->sensorPose;
			current = &moved;
			truth = p.truth + M;
			guess = diagonalPoseGaussian(p.truth + o.appliedMotion, sigmaXY, sigmaYaw);
		}
		else
			guess = diagonalPoseGaussian(
				mrpt::poses::CPose2D(p.truth.x() + dx, p.truth.y() + dy, p.truth.phi() + dw),
				sigmaXY, sigmaYaw);
		// Which of the current scan's points the matchers keep (with the
		// world known): their parts' beams against the moved ones.
		std::optional<ScanPoints> refPoints, curPoints;
		if (p.movedKnown)
		{
			refPoints = ScanPoints::fromScan(*p.reference);
			curPoints = ScanPoints::fromScan(*current);
		}
		for (size_t m = 0; m < matchers.size(); m++)
		{
			const MatchResult r = matchers[m]->match(*p.reference, *current, guess);
			if (p.movedKnown)
			{
				const mrpt::poses::CPose2D sensorEstimate =
					(mrpt::poses::CPose2D() - mrpt::poses::CPose2D(p.reference->sensorPose)) +
					r.estimate.mean + mrpt::poses::CPose2D(current->sensorPose);
				const MatchInspection in =
					matchers[m]->inspectLastMatch(*refPoints, *curPoints, sensorEstimate);
				for (const auto& part : in.parts)
				{
					if (!part.current) continue;
					for (uint32_t b : part.beams)
					{
						const bool moved = std::binary_search(
							p.movedBeams.begin(), p.movedBeams.end(), b);
						(moved ? res[m].movedSeen : res[m].stillSeen)++;
						if (part.kept) (moved ? res[m].movedKept : res[m].stillKept)++;
					}
				}
			}
			auto& a = acc[m];
			res[m].pairs++;
			a.time.push_back(r.timeSeconds);
			a.iterations += r.iterations;
			if (!r.matcherFallback.empty()) res[m].matcherFallbacks++;
			if (r.segmentsDroppedByResiduals > 0) res[m].segmentsDroppedByResiduals++;
			if (r.confirmedShare > 0) res[m].searchSkipped++;
			if (r.confirmationSlid) res[m].confirmationsSlid++;
			if (r.guessKeptAlongFreeDirection) res[m].guessKeptAlongFreeDirection++;
			if (!r.primaryFailure.empty())
			{
				res[m].fallbackMatches++;
				if (r.success) res[m].fallbackSuccesses++;
			}
			// Every pair counts: a failed match with the guess, which is what
			// the pipeline then uses.
			const auto& e = r.success ? r.estimate.mean : guess.mean;
			const Eigen::Vector3d err = poseDifference(e, truth);
			auto& outcome = res[m].outcomes.emplace_back();
			outcome.status = !r.success ? PairOutcome::Status::Failed
				: r.ambiguous			? PairOutcome::Status::Ambiguous
										: PairOutcome::Status::Used;
			outcome.error = err;
			outcome.reason = !r.success ? r.failureReason : r.ambiguous ? r.ambiguityReason : "";
			outcome.cov = (r.success ? r.estimate.cov : guess.cov).asEigen();
			const double et = std::hypot(err[0], err[1]), ew = std::abs(err[2]);
			const bool gross = et > o.grossTrans || ew > o.grossYaw;
			if (gross) res[m].grossUsed++;
			a.ex.push_back(std::abs(err[0]));
			a.ey.push_back(std::abs(err[1]));
			a.ew.push_back(ew);
			a.et.push_back(et);
			if (p.bound && p.bound->bounded && !o.applyMotion)
			{
				res[m].boundedPairs++;
				a.boundedTrans += et;
				a.boundedYaw += ew;
				a.boundTrans += p.bound->meanTrans;
				a.boundYaw += p.bound->meanYaw;
			}
			if (!r.success)
			{
				res[m].failures++;
				res[m].failuresByKind[r.failureKind]++;
				if (res[m].failureExamples.size() < 5)
					res[m].failureExamples.push_back(
						"pair " + std::to_string(k) + ": " + r.failureReason);
				continue;
			}
			if (r.ambiguous)
			{
				// Used with its covariance grown over the rivals: flagged,
				// and its error is what the pipeline uses.
				res[m].ambiguousUsed++;
				if (res[m].failureExamples.size() < 5)
					res[m].failureExamples.push_back(
						"pair " + std::to_string(k) + " (used, covariance inflated): " + r.ambiguityReason);
			}
			else if (gross)
			{
				res[m].silentGross++;
				if (res[m].silentGrossExamples.size() < 5)
				{
					char buf[160];
					std::snprintf(buf, sizeof(buf), "pair %zu: off by %.3f m, %.2f deg", k, et,
						mrpt::RAD2DEG(ew));
					res[m].silentGrossExamples.push_back(buf);
				}
			}
			a.nees.push_back(err.dot(r.estimate.cov.asEigen().ldlt().solve(err)));
		}
		if (progress) progress(k + 1);
	}
	for (size_t m = 0; m < matchers.size(); m++)
	{
		const auto& a = acc[m];
		auto& r = res[m];
		r.maeX = ErrorStats::of(a.ex).mean;
		r.maeY = ErrorStats::of(a.ey).mean;
		const auto w = ErrorStats::of(a.ew);
		r.maeYaw = w.mean;
		r.medianYaw = w.median;
		r.p95Yaw = w.p95;
		const auto t = ErrorStats::of(a.et);
		r.meanTrans = t.mean;
		r.medianTrans = t.median;
		r.p95Trans = t.p95;
		const auto time = ErrorStats::of(a.time);
		r.meanTime = time.mean;
		r.medianTime = time.median;
		r.meanIterations = r.pairs ? a.iterations / static_cast<double>(r.pairs) : 0;
		if (r.boundedPairs > 0)
		{
			const double n = static_cast<double>(r.boundedPairs);
			r.boundedMeanTrans = a.boundedTrans / n;
			r.boundedMeanYaw = a.boundedYaw / n;
			r.boundMeanTrans = a.boundTrans / n;
			r.boundMeanYaw = a.boundYaw / n;
		}
		const auto nees = ErrorStats::of(a.nees);
		r.meanNees = nees.mean;
		r.medianNees = nees.median;
		r.neesWithin95 = a.nees.empty()
			? 0.0
			: static_cast<double>(std::count_if(a.nees.begin(), a.nees.end(),
				  [](double v) { return v <= EvaluationReport::kNeesBound95; })) /
				static_cast<double>(a.nees.size());
	}
	return res;
}
}  // namespace featloc
