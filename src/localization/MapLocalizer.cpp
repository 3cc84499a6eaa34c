#include "featloc/localization/MapLocalizer.h"

#include <mrpt/core/bits_math.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <algorithm>
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
	// Lost, or only a map match less certain than it says? The map
	// decides: the scan where the estimate puts it against the best place
	// anywhere in the map.
	globalSearch();
	// (Both on the sharp table: the search's own scores are on its wide one.)
	const auto here = placed(*step.scan, estimator.pose().mean);
	out.global = m_global->search(*step.scan);
	const auto there = placed(*step.scan, out.global->best);
	if (here.score >= m_options.global_min_score &&
		here.score >= there.score - m_options.global_min_evidence / m_options.global_confirm_scans)
	{
		m_misses = 0;  // still where the estimate says: not lost
		return;
	}
	m_tracking = false;
	m_hypotheses.clear();
	m_window.clear();
	m_odometrySince = mrpt::poses::CPose2D();
	out.event = "lost";
	char buf[200];
	std::snprintf(buf, sizeof(buf),
		"; the scan scores %.0f%% at the estimate, %.0f%% at the best place in the map (its points "
		"on the map less its beams through the map)",
		100 * here.score, 100 * there.score);
	out.message = std::to_string(m_misses) + " scans in a row without a usable map match (last: " +
		out.reason + ")" + buf;
	m_misses = 0;
}

MapLocalizer::Placement MapLocalizer::placed(
	const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::poses::CPose2D& around) const
{
	const auto local = m_global->refine(scan, around, kTrackXY, kTrackYaw);
	Placement out{local.pose, local.score, 0};
	std::vector<bool> through;
	out.logLikelihood = logLikelihoodAt(scan, local.pose, through);
	if (m_options.global_see_through) out.score -= LocalizationMap::shareOf(through);
	return out;
}

double MapLocalizer::logLikelihoodAt(const mrpt::obs::CObservation2DRangeScan& scan,
	const mrpt::poses::CPose2D& pose, std::vector<bool>& through) const
{
	through = m_map->beamsSeenThrough(scan, pose);
	const auto hits = m_global->beamHits(scan, pose);
	double sum = 0;
	for (size_t i = 0; i < hits.size() && i < through.size(); i++)
	{
		const bool t = m_options.global_see_through && through[i];
		sum += t ? std::log(kThrough) : std::log(kStray + (1 - kStray) * hits[i]);
	}
	return sum;
}

double MapLocalizer::Hypothesis::totalLogLikelihood() const
{
	double sum = 0;
	for (const auto& p : scans) sum += p.logLikelihood;
	return sum;
}

double MapLocalizer::Hypothesis::total() const
{
	double sum = 0;
	for (const auto& p : scans) sum += p.score;
	return sum;
}

MapLocalizer::Hypothesis MapLocalizer::backdated(const mrpt::poses::CPose2D& pose) const
{
	// Scored on the sharp table on the last scan too, as the hypotheses
	// moved by odometry are: the search's own score is on its wide table,
	// higher, and would give a new hypothesis a head start.
	const auto last = placed(*m_window.back().scan, pose);
	Hypothesis h{last.pose, {last}};
	mrpt::poses::CPose2D at = last.pose;
	for (size_t j = m_window.size() - 1; j-- > 0;)
	{
		// Scan j+1 = scan j (+) odometry: back to scan j.
		at = at + (mrpt::poses::CPose2D() - m_window[j + 1].odometryFromPrevious);
		const auto local = placed(*m_window[j].scan, at);
		at = local.pose;
		h.scans.push_front(local);
	}
	return h;
}

const MapLocalizer::Hypothesis* MapLocalizer::confirmed() const
{
	const size_t k = m_options.global_confirm_scans;
	// The scans must prefer the hypothesis over every other: by the total
	// share of points, or by the log-likelihood.
	auto preferred = [&](auto measure, double margin) -> const Hypothesis* {
		const Hypothesis* best = nullptr;
		for (const auto& h : m_hypotheses)
			if (!best || measure(h) > measure(*best)) best = &h;
		if (!best || best->scans.size() < k) return nullptr;
		for (size_t i = best->scans.size() - k; i < best->scans.size(); i++)
			if (best->scans[i].score < m_options.global_min_score) return nullptr;
		for (const auto& h : m_hypotheses)
			if (&h != best && measure(*best) - measure(h) < margin) return nullptr;
		return best;
	};
	if (const auto* h = preferred([](const Hypothesis& h) { return h.total(); },
			m_options.global_min_evidence))
		return h;
	if (m_options.global_min_log_evidence <= 0) return nullptr;
	return preferred([](const Hypothesis& h) { return h.totalLogLikelihood(); },
		m_options.global_min_log_evidence);
}

void MapLocalizer::globalSearch()
{
	if (m_global) return;
	GlobalMapSearch::Options o;
	o.resolution = m_options.global_resolution;
	o.hitSigma = 2 * m_options.global_resolution;
	m_global = std::make_unique<GlobalMapSearch>(*m_map, o);
}

void MapLocalizer::search(const EstimationStep& step, PoseEstimator& estimator, Outcome& out)
{
	globalSearch();
	m_window.push_back({step.scan, m_odometrySince});
	// Every hypothesis moved by the odometry and put back on the map.
	for (auto& h : m_hypotheses)
	{
		const auto local = placed(*step.scan, h.pose + m_odometrySince);
		h.pose = local.pose;
		h.scans.push_back(local);
	}
	m_odometrySince = mrpt::poses::CPose2D();
	if (m_window.size() > kMaxWindow)
	{
		m_window.pop_front();
		for (auto& h : m_hypotheses) h.scans.pop_front();
	}
	auto same = [](const mrpt::poses::CPose2D& a, const mrpt::poses::CPose2D& b) {
		return posesWithin(a, b, kSameXY, kSameYaw);
	};
	// Hypotheses that the map pulled to one place are one (the best record
	// stays); weak ones go.
	std::sort(m_hypotheses.begin(), m_hypotheses.end(),
		[](const Hypothesis& a, const Hypothesis& b) { return a.total() > b.total(); });
	std::vector<Hypothesis> kept;
	for (auto& h : m_hypotheses)
	{
		if (h.scans.back().score < m_options.global_min_score) continue;
		bool duplicate = false;
		for (const auto& k : kept) duplicate = duplicate || same(h.pose, k.pose);
		if (!duplicate && kept.size() < kMaxHypotheses) kept.push_back(std::move(h));
	}
	m_hypotheses.swap(kept);
	// The whole map: its best pose and best rival, where no hypothesis is,
	// judged on the earlier scans too.
	out.global = m_global->search(*step.scan);
	const auto& g = *out.global;
	auto add = [&](const mrpt::poses::CPose2D& p, double score) {
		if (score < m_options.global_min_score) return;
		for (const auto& h : m_hypotheses)
			if (same(p, h.pose)) return;
		m_hypotheses.push_back(backdated(p));
	};
	if (g.valid)
	{
		add(g.best, g.bestScore);
		add(g.rival, g.rivalScore);
		for (const auto& c : g.contenders) add(c.pose, c.score);
	}
	const Hypothesis* h = confirmed();
	if (!h) return;

	// Found: refine by a map match from the hypothesis, restart the
	// estimator there.
	const double res = m_options.global_resolution;
	mrpt::math::CMatrixDouble33 gridCov;
	gridCov(0, 0) = gridCov(1, 1) = res * res;
	gridCov(2, 2) = mrpt::square(mrpt::DEG2RAD(2.0));
	mrpt::poses::CPosePDFGaussian start(h->pose, gridCov);
	double runnerUp = -1, runnerUpLogLikelihood = -HUGE_VAL;
	for (const auto& o : m_hypotheses)
		if (&o != h)
		{
			runnerUp = std::max(runnerUp, o.total());
			runnerUpLogLikelihood = std::max(runnerUpLogLikelihood, o.totalLogLikelihood());
		}
	const double n = static_cast<double>(h->scans.size());
	char buf[300];
	std::snprintf(buf, sizeof(buf),
		"scored %.0f%% over %zu scans (points on the map less beams through it); the next of %zu "
		"hypotheses %.0f%%",
		100 * h->total() / n, h->scans.size(), m_hypotheses.size(),
		runnerUp < 0 ? 0.0 : 100 * runnerUp / n);
	std::string evidence = buf;
	// Which rule found it shows in the log-likelihood lead (either may).
	if (std::isfinite(runnerUpLogLikelihood))
	{
		std::snprintf(buf, sizeof(buf), "; log-likelihood %.0f nats above the next",
			h->totalLogLikelihood() - runnerUpLogLikelihood);
		evidence += buf;
	}
	// The map match refines the hypothesis, and the map judges the
	// refinement: where the scan fits the map far worse at the match than
	// at the hypothesis, the robot is found at the hypothesis, with the
	// search grid's covariance. (Held-out office start 182, in the far
	// corner facing away from both near walls: PCM on the virtual scan
	// walked 0.245 m from a hypothesis 4 cm from the truth, along the
	// direction the far walls leave loose, 556 nats worse on the map, and
	// the robot was "found" 3.4 sigma off.)
	const auto refined = m_tracker.track(*step.scan, start);
	if (refined.match.success)
	{
		// The hypothesis's own placement on this scan is at h->pose: its
		// log-likelihood there is already known.
		std::vector<bool> through;
		const double lead = h->scans.back().logLikelihood -
			logLikelihoodAt(*step.scan, refined.pose.mean, through);
		if (lead <= kRefinementLead)
			start = refined.pose;
		else
		{
			std::snprintf(buf, sizeof(buf),
				"; its map match (%.3f m, %.3f m, %.1f deg) not used: %.0f nats less likely on "
				"the map",
				refined.pose.mean.x(), refined.pose.mean.y(),
				mrpt::RAD2DEG(refined.pose.mean.phi()), lead);
			evidence += buf;
		}
	}
	estimator.initialize(start);
	m_tracking = true;
	m_misses = 0;
	m_hypotheses.clear();
	m_window.clear();
	out.event = "found";
	std::snprintf(buf, sizeof(buf), "at (%.3f m, %.3f m, %.1f deg), ", start.mean.x(),
		start.mean.y(), mrpt::RAD2DEG(start.mean.phi()));
	out.message = buf + evidence;
}
}  // namespace featloc
