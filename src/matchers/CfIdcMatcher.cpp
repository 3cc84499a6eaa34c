#include "featloc/matchers/CfIdcMatcher.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "featloc/config/ConfigValues.h"
#include "featloc/matchers/SegmentResidualTest.h"

namespace featloc
{
IMPLEMENTS_MRPT_OBJECT(CfIdcMatcher, ScanMatcher, featloc)

namespace
{
/** IDC starts from every segment large enough when the curvature pairing
 * keeps less than 1/kMinPairedShare of their points. */
constexpr size_t kMinPairedShare = 3;
/** Metric curvature sampling: at most this many samples per function (the
 * step grows for very long segments), so the FFTs stay short. */
constexpr double kMaxCurvatureSamples = 128;
}  // namespace

void CfIdcMatcher::Parameters::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	using namespace featloc::config;
	segmentation.loadFromConfigFile(c, s);
	read(c, s, "min_segment_points", min_segment_points);
	curvature.loadFromConfigFile(c, s);
	correlation.loadFromConfigFile(c, s);
	read(c, s, "curvature_pairing", curvature_pairing);
	read(c, s, "pairing_gate", pairing_gate);
	read(c, s, "pairing_fallback", pairing_fallback);
	read(c, s, "segment_gate", segment_gate);
	read(c, s, "segment_gate_from_lattice", segment_gate_from_lattice);
	read(c, s, "segment_residual_chi2", segment_residual_chi2);
	idc.loadFromConfigFile(c, s);
	require(segment_residual_chi2 >= 0, c, s, "segment_residual_chi2", ">= 0 (0 disables it)");
	require(min_segment_points >= 2, c, s, "min_segment_points", ">= 2");
	require(segment_gate >= 0, c, s, "segment_gate", ">= 0 (0 disables it)");
}

void CfIdcMatcher::Parameters::saveToConfigFile(
	mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	using namespace featloc::config;
	segmentation.saveToConfigFile(c, s);
	write(c, s, "min_segment_points", min_segment_points,
		"segments with fewer points are dropped (isolated groups)");
	curvature.saveToConfigFile(c, s);
	correlation.saveToConfigFile(c, s);
	write(c, s, "curvature_pairing", curvature_pairing,
		"pair the segments' curvature functions and drop the unpaired ones (CF-SMA2; false: every segment goes to IDC, an ablation)");
	write(c, s, "pairing_gate", pairing_gate,
		"compare only segments that can be the same object under the initial guess (false: the paper)");
	write(c, s, "pairing_fallback", pairing_fallback,
		"if the curvature pairing keeps under a third of the points, IDC starts from every segment (false: the paper, IDC on what was paired)");
	write(c, s, "segment_gate", segment_gate,
		"[m] keep the current segments within this (median) of the reference once IDC has converged, twice this at its switch to point-to-line (0: the paper's pairing decides)");
	write(c, s, "segment_gate_from_lattice", segment_gate_from_lattice,
		"the segment gate is at least the step of a range lattice the current scan's ranges sit on (MRPT's simulated log: 0.16 m), which can put a static segment that far off the reference (false: segment_gate alone)");
	write(c, s, "segment_residual_chi2", segment_residual_chi2,
		"with segment_gate: at the gate's final test, a kept segment whose residuals at the estimate (an offset and a slope along it) exceed this chi-square under the range noise is dropped as moved, most discordant first, up to a third of the kept points (a door that turned, a cart pushed a few cm; 0: off)");
	idc.saveToConfigFile(c, s);
}

void CfIdcMatcher::loadOwnParams(const mrpt::config::CConfigFileBase& cfg, const std::string& section)
{
	params.loadFromConfigFile(cfg, section);
}

void CfIdcMatcher::saveOwnParams(mrpt::config::CConfigFileBase& cfg, const std::string& section) const
{
	params.saveToConfigFile(cfg, section);
}

void CfIdcMatcher::describe(
	const ScanPoints& scan, std::vector<SegmentReport>& report,
	std::vector<std::vector<double>>& functions, std::vector<int>& segmentOf)
{
	// report holds the segments already (matchPoints).
	functions.resize(report.size());
	segmentOf.clear();
	size_t used = 0;
	for (size_t k = 0; k < report.size(); k++)
	{
		const ScanSegment& seg = report[k].segment;
		if (seg.size() < params.min_segment_points)
		{
			report[k].reason =
				"too small (" + std::to_string(seg.size()) + " points < min_segment_points)";
			continue;
		}
		m_curvature.compute(scan, seg, functions[used++], m_curvatureStep);
		segmentOf.push_back(static_cast<int>(k));
	}
	functions.resize(used);
}

namespace
{
/** Axis-aligned bounding box of a segment's points, moved by (c, s, tx, ty). */
struct Box
{
	double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;

	void add(double x, double y)
	{
		x0 = std::min(x0, x);
		y0 = std::min(y0, y);
		x1 = std::max(x1, x);
		y1 = std::max(y1, y);
	}
	/** Distance between two boxes (0 if they overlap). */
	double distance(const Box& o) const
	{
		const double dx = std::max({0.0, o.x0 - x1, x0 - o.x1});
		const double dy = std::max({0.0, o.y0 - y1, y0 - o.y1});
		return std::hypot(dx, dy);
	}
};

Box boxOf(const ScanPoints& scan, const ScanSegment& seg, double c = 1, double s = 0,
	double tx = 0, double ty = 0)
{
	Box b;
	for (uint32_t i = seg.first; i <= seg.last; i++)
	{
		const ScanPoint& p = scan.points[i];
		b.add(c * p.x - s * p.y + tx, s * p.x + c * p.y + ty);
	}
	return b;
}
}  // namespace

void CfIdcMatcher::plausiblePairs(
	const ScanPoints& reference, const ScanPoints& current,
	const mrpt::poses::CPosePDFGaussian& guess)
{
	const size_t nc = m_currentSegmentOf.size(), nr = m_referenceSegmentOf.size();
	m_allowed.assign(nc * nr, 1);
	if (!params.pairing_gate) return;
	const auto& G = guess.cov;
	const double sxy = std::sqrt(std::max({G(0, 0), G(1, 1), 0.0}));
	const double sw = std::sqrt(std::max(G(2, 2), 0.0));
	const double c = std::cos(guess.mean.phi()), s = std::sin(guess.mean.phi());
	std::vector<Box> ref(nr);
	for (size_t j = 0; j < nr; j++)
		ref[j] = boxOf(reference, m_referenceReport[static_cast<size_t>(m_referenceSegmentOf[j])].segment);
	for (size_t i = 0; i < nc; i++)
	{
		// The segment in the reference frame under the guess, and how far the
		// guess's uncertainty can move its farthest point.
		const ScanSegment& seg = m_currentReport[static_cast<size_t>(m_currentSegmentOf[i])].segment;
		const Box box = boxOf(current, seg, c, s, guess.mean.x(), guess.mean.y());
		double farthest = 0;
		for (uint32_t k = seg.first; k <= seg.last; k++)
			farthest = std::max(farthest, current.points[k].range);
		const double window = params.idc.window_sigmas * (sxy + sw * farthest);
		for (size_t j = 0; j < nr; j++) m_allowed[i * nr + j] = box.distance(ref[j]) <= window;
	}
}

void CfIdcMatcher::pairSegments()
{
	for (const auto& m : m_matches)
	{
		SegmentReport& c = m_currentReport[static_cast<size_t>(m_currentSegmentOf[m.current])];
		SegmentReport& r = m_referenceReport[static_cast<size_t>(m_referenceSegmentOf[m.reference])];
		c.kept = r.kept = true;
		c.pairedWith = m_referenceSegmentOf[m.reference];
		r.pairedWith = m_currentSegmentOf[m.current];
		c.similarity = r.similarity = m.similarity;
	}
	const auto& rho = m_correlator.lastSimilarity();
	const size_t nc = m_currentFunctions.size(), nr = m_referenceFunctions.size();
	auto unpaired = [&](std::vector<SegmentReport>& report, const std::vector<int>& segmentOf,
						bool isCurrent) {
		for (size_t f = 0; f < segmentOf.size(); f++)
		{
			SegmentReport& s = report[static_cast<size_t>(segmentOf[f])];
			if (s.kept) continue;
			double best = 0;
			bool any = false;
			for (size_t o = 0; o < (isCurrent ? nr : nc); o++)
			{
				const size_t at = isCurrent ? f * nr + o : o * nr + f;
				if (!m_allowed[at]) continue;
				any = true;
				best = std::max(best, rho[at]);
			}
			s.similarity = best;
			char buf[160];
			if (!any)
				std::snprintf(buf, sizeof(buf), "no curvature match (nothing near it under the guess)");
			else
				std::snprintf(buf, sizeof(buf), "no curvature match (best similarity %.2f%s)", best,
					best >= params.correlation.U_c ? ", its partner was taken" : " < U_c");
			s.reason = buf;
		}
	};
	unpaired(m_currentReport, m_currentSegmentOf, true);
	unpaired(m_referenceReport, m_referenceSegmentOf, false);
}

void CfIdcMatcher::buildReference(const ScanPoints& reference)
{
	m_segments.clear();
	for (const auto& s : m_referenceReport)
		if (s.kept) m_segments.push_back(s.segment);
	m_polyline.build(reference, m_segments, params.idc.line_half_window,
		lineGrowthTargetFor(params.idc.lineTargetDirectionSigma()), params.idc.line_bow_sigmas,
		params.idc.circle_fit_sigmas, params.idc.face_segment_extent, params.idc.line_bow_per_segment);
}

void CfIdcMatcher::collectKeptCurrent(const ScanPoints& current)
{
	m_kept.clear();
	for (const auto& s : m_currentReport)
		if (s.kept)
			m_kept.insert(m_kept.end(), current.points.begin() + s.segment.first,
				current.points.begin() + s.segment.last + 1);
}

void CfIdcMatcher::dropMovedByResiduals(const ScanPoints& current, const mrpt::math::TPose2D& x)
{
	// The residuals' noise: the reference's (its local lines were fitted
	// to it), not below IDC's floor or a range lattice's cell.
	const double sigma =
		std::max({m_polyline.rangeNoise(), params.idc.min_range_sigma, rangeLatticeCellSigma()});
	struct Moved
	{
		size_t segment;
		SegmentResidualTest::Result test;
	};
	std::vector<Moved> moved;
	size_t kept = 0;
	for (size_t k = 0; k < m_currentReport.size(); k++)
	{
		const SegmentReport& s = m_currentReport[k];
		if (!s.kept) continue;
		kept += s.segment.size();
		// What IDC pairs at the end: points within its least pairing
		// distance of a reference line.
		const auto test = SegmentResidualTest::run(
			m_polyline, current, s.segment, x, sigma, params.idc.min_pair_distance);
		if (test.points >= params.min_segment_points && test.chi2 > params.segment_residual_chi2)
			moved.push_back({k, test});
	}
	std::sort(moved.begin(), moved.end(),
		[](const Moved& a, const Moved& b) { return a.test.chi2 > b.test.chi2; });
	size_t dropped = 0;
	for (const Moved& m : moved)
	{
		SegmentReport& s = m_currentReport[m.segment];
		if (static_cast<double>(dropped + s.segment.size()) > kMaxMovedShare * static_cast<double>(kept))
			continue;
		dropped += s.segment.size();
		s.kept = false;
		char buf[220];
		std::snprintf(buf, sizeof(buf),
			"%s at the estimate, %.3f m %+.3f m per m along it, give a chi-square of %.0f > %.0f "
			"(segment_residual_chi2)",
			kMovedByResiduals, m.test.offset, m.test.slope, m.test.chi2, params.segment_residual_chi2);
		s.reason = buf;
	}
}

bool CfIdcMatcher::reselect(
	const ScanPoints& reference, const ScanPoints& current, const mrpt::math::TPose2D& x,
	double gate, bool testResiduals)
{
	// Kept as they are if the estimate is too poor for the test to leave
	// enough points (IDC then fails or succeeds on the pairing's choice).
	// Every segment is judged by geometry now, the small ones too: a door
	// jamb of three points may be all that fixes the motion along a
	// corridor, and a person's leg that moved goes either way.
	const auto currentBefore = m_currentReport, referenceBefore = m_referenceReport;
	bool referenceChanged = false;
	for (auto& s : m_referenceReport)
	{
		referenceChanged = referenceChanged || !s.kept;
		s.kept = true;
		s.reason.clear();
	}
	if (referenceChanged) buildReference(reference);
	for (auto& s : m_currentReport)
	{
		const double d = IterativeDualCorrespondence::medianDistance(
			m_polyline, &current.points[s.segment.first], s.segment.size(), x, 4 * gate);
		char buf[200];
		if (d <= gate)
		{
			if (!s.kept)
			{
				std::snprintf(buf, sizeof(buf),
					"kept: lies on the reference at the estimate (median distance %.3f m), "
					"though %s",
					d,
					s.segment.size() < params.min_segment_points ? "too small for CF-SMA1"
																  : "its curvature was not paired");
				s.reason = buf;
			}
			s.kept = true;
			continue;
		}
		std::snprintf(buf, sizeof(buf),
			"moved: median distance %s%.3f m to the reference at the estimate > %.3f m "
			"(segment_gate, or the step of the ranges' lattice)",
			d >= 4 * gate ? ">= " : "", d, gate);
		s.kept = false;
		s.reason = buf;
	}
	if (testResiduals && params.segment_residual_chi2 > 0) dropMovedByResiduals(current, x);
	collectKeptCurrent(current);
	if (m_kept.size() < 3 * params.idc.min_pairs)
	{
		m_currentReport = currentBefore;
		m_referenceReport = referenceBefore;
		buildReference(reference);
		collectKeptCurrent(current);
		return false;
	}
	for (size_t k = 0; k < m_currentReport.size(); k++)
		if (m_currentReport[k].kept != currentBefore[k].kept) return true;
	for (size_t k = 0; k < m_referenceReport.size(); k++)
		if (m_referenceReport[k].kept != referenceBefore[k].kept) return true;
	return false;
}

void CfIdcMatcher::matchPoints(
	const ScanPoints& reference, const ScanPoints& current,
	const mrpt::poses::CPosePDFGaussian& initialGuess, MatchResult& result)
{
	m_segmenter.params = segmentationFor(params.segmentation);
	m_curvature.params = params.curvature;
	m_correlator.params = params.correlation;
	m_idc.params = params.idc;
	m_idc.params.max_face_direction_sigma = faceDirectionSigmaFor(params.idc.max_face_direction_sigma);
	m_idc.rangeLatticeCellSigma = rangeLatticeCellSigma();
	result.success = false;
	result.iterations = 0;
	result.estimate = initialGuess;

	// CF-SMA1. Metric sampling: one step for both scans, coarser than
	// curvature_step if needed to bound the FFT length.
	m_curvatureStep = params.curvature.step;
	for (auto [scan, report] : {std::make_pair(&reference, &m_referenceReport),
			 std::make_pair(&current, &m_currentReport)})
	{
		m_segmenter.segment(*scan, m_segments);
		report->assign(m_segments.size(), SegmentReport());
		for (size_t k = 0; k < m_segments.size(); k++)
		{
			(*report)[k].segment = m_segments[k];
			if (params.curvature.sampling == "metric")
				m_curvatureStep = std::max(m_curvatureStep,
					CurvatureFunction::arcLength(*scan, m_segments[k]) / kMaxCurvatureSamples);
		}
	}
	describe(reference, m_referenceReport, m_referenceFunctions, m_referenceSegmentOf);
	describe(current, m_currentReport, m_currentFunctions, m_currentSegmentOf);

	// CF-SMA2: pair the curvature functions; unpaired segments are dropped.
	if (params.curvature_pairing)
	{
		plausiblePairs(reference, current, initialGuess);
		m_correlator.match(m_currentFunctions, m_referenceFunctions, m_allowed,
			params.curvature.sampling == "normalized", m_matches);
		pairSegments();
	}
	else
		for (auto* report : {&m_currentReport, &m_referenceReport})
			for (auto& s : *report)
				if (s.segment.size() >= params.min_segment_points)
				{
					s.kept = true;
					s.reason = "kept: curvature_pairing is off";
				}
	buildReference(reference);
	collectKeptCurrent(current);
	size_t sizeable = 0;
	for (const auto& s : m_currentReport)
		if (s.segment.size() >= params.min_segment_points) sizeable += s.segment.size();
	if (params.pairing_fallback &&
		(m_kept.size() < std::max<size_t>(3 * params.idc.min_pairs, sizeable / kMinPairedShare) ||
			m_polyline.size() < 3 * params.idc.min_pairs))
	{
		result.matcherFallback = "the curvature pairing kept " + std::to_string(m_kept.size()) +
			" of " + std::to_string(sizeable) + " points: IDC started from every segment";
		// Too little paired to start from: every segment large enough.
		for (auto* report : {&m_currentReport, &m_referenceReport})
			for (auto& s : *report)
				if (s.segment.size() >= params.min_segment_points && !s.kept)
				{
					s.kept = true;
					s.reason = "kept: the curvature pairing left too few points to start IDC from";
				}
		buildReference(reference);
		collectKeptCurrent(current);
	}
	if (m_kept.empty() || m_polyline.size() == 0)
	{
		result.failureReason = "no segment of " + std::to_string(params.min_segment_points) +
			" points or more in the " + (m_kept.empty() ? "current" : "reference") + " scan";
		return;
	}

	// CF-SMA3: IDC on the kept points; featloc's segment gate at the switch
	// to the point-to-line phase.
	IterativeDualCorrespondence::PhaseSwitch reselectAtSwitch;
	IterativeDualCorrespondence::Revision reselectAtEnd;
	if (params.segment_gate > 0)
	{
		// Ranges on a lattice of step q (RangeLattice) make a static
		// surface a run of arcs around each sensor: at the true motion the
		// current arcs lie up to q off the reference's, and at "no
		// motion" on them. A gate tighter than q drops the segments that
		// fix the motion and keeps the arcs that hold it at zero (MRPT's
		// simulated log, q = 0.16 m: a matcher chain of 903 mm).
		const double gate = params.segment_gate_from_lattice
			? std::max(params.segment_gate, rangeLatticeStep())
			: params.segment_gate;
		// Centimetres off still at the switch: a looser gate there, so that
		// the few points that fix a weak direction are not judged by an
		// estimate that is wrong along it; the segment gate proper at the end.
		reselectAtSwitch = [&reference, &current, gate, this](const mrpt::math::TPose2D& x) {
			reselect(reference, current, x, 2 * gate, false);
		};
		reselectAtEnd = [&reference, &current, gate, this](const mrpt::math::TPose2D& x) {
			return reselect(reference, current, x, gate, true);
		};
	}
	IterativeDualCorrespondence::Result r;
	m_idc.run(m_polyline, m_kept, initialGuess, r, reselectAtSwitch, reselectAtEnd);

	result.currentPoints = m_kept.size();
	result.referencePoints = m_polyline.size();
	for (const auto& s : m_currentReport)
		result.segmentsDroppedByResiduals += !s.kept && s.reason.rfind(kMovedByResiduals, 0) == 0;
	result.success = r.success;
	result.failureReason = r.failureReason;
	result.iterations = r.iterations;
	result.estimate.mean = mrpt::poses::CPose2D(r.estimate);
	result.estimate.cov = r.cov;
	result.freeDirection = r.freeDirection;
	result.goodness = current.empty()
		? 0.0
		: static_cast<double>(r.pairs) / static_cast<double>(current.size());
}
MatchInspection CfIdcMatcher::inspectOwnMatch(const ScanPoints& reference,
	const ScanPoints& current, const mrpt::poses::CPose2D& sensorEstimate) const
{
	// IDC's pairs as the base class finds them, plus every segment of both
	// scans with the curvature-function decision of section 3.
	MatchInspection out = ScanMatcher::inspectOwnMatch(reference, current, sensorEstimate);
	auto addParts = [&](const std::vector<SegmentReport>& report, const ScanPoints& scan,
						bool isCurrent) {
		for (const auto& r : report)
		{
			MatchInspection::Part part;
			part.current = isCurrent;
			part.kept = r.kept;
			part.kind = "segment";
			for (uint32_t i = r.segment.first; i <= r.segment.last && i < scan.size(); i++)
			{
				part.points.push_back({scan.points[i].x, scan.points[i].y});
				part.beams.push_back(scan.points[i].beam);
			}
			part.note = r.reason;
			out.parts.push_back(std::move(part));
		}
	};
	addParts(m_referenceReport, reference, false);
	addParts(m_currentReport, current, true);
	return out;
}
}  // namespace featloc
