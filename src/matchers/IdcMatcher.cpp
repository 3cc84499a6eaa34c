#include "featloc/matchers/IdcMatcher.h"

#include <algorithm>

namespace featloc
{
IMPLEMENTS_MRPT_OBJECT(IdcMatcher, ScanMatcher, featloc)

void IdcMatcher::Parameters::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	segmentation.loadFromConfigFile(c, s);
	idc.loadFromConfigFile(c, s);
}

void IdcMatcher::Parameters::saveToConfigFile(
	mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	segmentation.saveToConfigFile(c, s);
	idc.saveToConfigFile(c, s);
}

void IdcMatcher::loadOwnParams(const mrpt::config::CConfigFileBase& cfg, const std::string& section)
{
	params.loadFromConfigFile(cfg, section);
}

void IdcMatcher::saveOwnParams(mrpt::config::CConfigFileBase& cfg, const std::string& section) const
{
	params.saveToConfigFile(cfg, section);
}

void IdcMatcher::buildReference(const ScanPoints& reference)
{
	// One build serves every match against the same scan: a keyframe's,
	// and the second run of the iterations when coarse_confirm_share sends
	// a match to the coarse search.
	const AdaptiveBreakpointSegmenter::Parameters segmentation = segmentationFor(params.segmentation);
	const double lineTarget = lineGrowthTargetFor(params.idc.lineTargetDirectionSigma());
	if (m_built && m_builtSegmentation == segmentation &&
		m_builtLineHalfWindow == params.idc.line_half_window && m_builtLineTarget == lineTarget &&
		m_builtBowSigmas == params.idc.line_bow_sigmas &&
		m_builtBowPerSegment == params.idc.line_bow_per_segment &&
		m_builtCircleSigmas == params.idc.circle_fit_sigmas &&
		m_builtRoundExtent == params.idc.face_segment_extent &&
		m_builtReference.samePointsAs(reference))
		return;
	AdaptiveBreakpointSegmenter(segmentation).segment(reference, m_segments);
	m_polyline.build(reference, m_segments, params.idc.line_half_window, lineTarget,
		params.idc.line_bow_sigmas, params.idc.circle_fit_sigmas, params.idc.face_segment_extent,
		params.idc.line_bow_per_segment);
	m_built = true;
	m_builtReference = reference;
	m_builtSegmentation = segmentation;
	m_builtLineHalfWindow = params.idc.line_half_window;
	m_builtLineTarget = lineTarget;
	m_builtBowSigmas = params.idc.line_bow_sigmas;
	m_builtBowPerSegment = params.idc.line_bow_per_segment;
	m_builtCircleSigmas = params.idc.circle_fit_sigmas;
	m_builtRoundExtent = params.idc.face_segment_extent;
}

void IdcMatcher::matchPoints(
	const ScanPoints& reference, const ScanPoints& current,
	const mrpt::poses::CPosePDFGaussian& initialGuess, MatchResult& result)
{
	buildReference(reference);
	m_idc.params = params.idc;
	m_idc.params.max_face_direction_sigma = faceDirectionSigmaFor(params.idc.max_face_direction_sigma);
	m_idc.rangeLatticeCellSigma = rangeLatticeCellSigma();
	IterativeDualCorrespondence::Result r;
	m_idc.run(m_polyline, current.points, initialGuess, r);
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
}  // namespace featloc
