#include "featloc/matchers/ScanMatcherAlignment.h"

#include <mrpt/maps/CPointsMap.h>
#include <mrpt/poses/CPose3DPDF.h>

#include <stdexcept>

namespace featloc
{
namespace
{
const mrpt::maps::CPointsMap& asPointsMap(
	const mrpt::maps::CMetricMap* m, const char* which)
{
	const auto* pm = dynamic_cast<const mrpt::maps::CPointsMap*>(m);
	if (!pm)
		throw std::invalid_argument(
			std::string("ScanMatcherAlignment: ") + which +
			" must be an mrpt::maps::CPointsMap, got " +
			(m ? m->GetRuntimeClass()->className : "nullptr"));
	return *pm;
}
}  // namespace

ScanMatcherAlignment::ScanMatcherAlignment(ScanMatcher::Ptr matcher)
	: m_matcher(std::move(matcher))
{
	if (!m_matcher)
		throw std::invalid_argument("ScanMatcherAlignment: null matcher");
}

mrpt::poses::CPosePDF::Ptr ScanMatcherAlignment::AlignPDF(
	const mrpt::maps::CMetricMap* m1, const mrpt::maps::CMetricMap* m2,
	const mrpt::poses::CPosePDFGaussian& initialEstimationPDF,
	mrpt::optional_ref<mrpt::slam::TMetricMapAlignmentResult> outInfo)
{
	const ScanPoints ref = ScanPoints::fromPointsMap(asPointsMap(m1, "m1"));
	const ScanPoints cur = ScanPoints::fromPointsMap(asPointsMap(m2, "m2"));
	const MatchResult r = m_matcher->match(ref, cur, initialEstimationPDF);
	if (outInfo)
	{
		outInfo->get().executionTime = r.timeSeconds;
		if (auto* full = dynamic_cast<TReturnInfo*>(&outInfo->get()))
			full->match = r;
	}
	return std::make_shared<mrpt::poses::CPosePDFGaussian>(r.estimate);
}

mrpt::poses::CPose3DPDF::Ptr ScanMatcherAlignment::Align3DPDF(
	const mrpt::maps::CMetricMap*, const mrpt::maps::CMetricMap*,
	const mrpt::poses::CPose3DPDFGaussian&,
	mrpt::optional_ref<mrpt::slam::TMetricMapAlignmentResult>)
{
	throw std::logic_error(
		"ScanMatcherAlignment: featloc matchers are planar; use AlignPDF()");
}

}  // namespace featloc
