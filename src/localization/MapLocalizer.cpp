#include "featloc/localization/MapLocalizer.h"

#include <mrpt/core/bits_math.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <cmath>
#include <cstdio>

#include "featloc/math/PoseDifference.h"

namespace featloc
{
MapLocalizer::MapLocalizer(std::shared_ptr<const LocalizationMap> map, ScanMatcher::Ptr matcher,
	LocalizationOptions options, bool startSearching)
	: m_map(map),
	  m_options(options),
	  m_tracker(map, std::move(matcher), options),
	  m_tracking(!startSearching)
{
}

MapLocalizer::Outcome MapLocalizer::process(const EstimationStep& step, PoseEstimator& estimator)
{
	Outcome out;
	if (step.index > 0) m_odometrySince = m_odometrySince + step.odometry.mean;
	if (!step.scan) return out;
	if (m_tracking)
		track(step, estimator, out);
	else
		search(step, estimator, out);
	return out;
}

void MapLocalizer::track(const EstimationStep& step, PoseEstimator& estimator, Outcome& out)
{
	out.mapMatch = m_tracker.track(*step.scan, estimator.pose());
	const auto& r = *out.mapMatch;
	if (r.match.success)
		out.used = estimator.fuseAbsolutePose(r.pose, m_options.gate_chi2, out.reason);
	else
		out.reason = "the map match failed: " + r.match.failureReason;
	m_misses = out.used ? 0 : m_misses + 1;
	if (m_options.lost_after_scans == 0 || m_misses < m_options.lost_after_scans) return;
	m_tracking = false;
	m_hypothesis.reset();
	m_streak = 0;
	out.event = "lost";
	out.message = std::to_string(m_misses) + " scans in a row without a usable map match (last: " +
		out.reason + ")";
	m_misses = 0;
}

void MapLocalizer::search(const EstimationStep& step, PoseEstimator& estimator, Outcome& out)
{
	if (!m_global)
	{
		GlobalMapSearch::Options o;
		o.resolution = m_options.global_resolution;
		o.hitSigma = 2 * m_options.global_resolution;
		m_global = std::make_unique<GlobalMapSearch>(*m_map, o);
	}
	out.global = m_global->search(*step.scan);
	const auto& g = *out.global;
	bool agrees = false;
	if (m_hypothesis)
	{
		const Eigen::Vector3d d = poseDifference(g.best, *m_hypothesis + m_odometrySince);
		agrees = std::hypot(d[0], d[1]) <= kConfirmDistance && std::abs(d[2]) <= kConfirmAngle;
	}
	m_odometrySince = mrpt::poses::CPose2D();
	if (!g.valid || g.bestScore < m_options.global_min_score)
	{
		m_hypothesis.reset();
		m_streak = 0;
		return;
	}
	m_streak = agrees ? m_streak + 1 : 1;
	m_hypothesis = g.best;
	if (m_streak < m_options.global_confirm_scans ||
		g.rivalScore >= m_options.global_rival_ratio * g.bestScore)
		return;

	// Found: refine by a map match from the search's grid pose, restart
	// the estimator there.
	const double res = m_options.global_resolution;
	mrpt::math::CMatrixDouble33 gridCov;
	gridCov(0, 0) = gridCov(1, 1) = res * res;
	gridCov(2, 2) = mrpt::square(mrpt::DEG2RAD(2.0));
	mrpt::poses::CPosePDFGaussian start(g.best, gridCov);
	const auto refined = m_tracker.track(*step.scan, start);
	if (refined.match.success) start = refined.pose;
	estimator.initialize(start);
	m_tracking = true;
	m_misses = 0;
	m_streak = 0;
	m_hypothesis.reset();
	out.event = "found";
	char buf[240];
	std::snprintf(buf, sizeof(buf),
		"at (%.3f m, %.3f m, %.1f deg), %.0f%% of the scan on the map, best rival %.0f%% "
		"(%.2f m, %.1f deg away); %u scans agreed",
		start.mean.x(), start.mean.y(), mrpt::RAD2DEG(start.mean.phi()), 100 * g.bestScore,
		100 * g.rivalScore, std::hypot(g.rival.x() - g.best.x(), g.rival.y() - g.best.y()),
		mrpt::RAD2DEG(mrpt::math::wrapToPi(g.rival.phi() - g.best.phi())),
		m_options.global_confirm_scans);
	out.message = buf;
}
}  // namespace featloc
