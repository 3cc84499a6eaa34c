#pragma once
#include <mrpt/slam/CMetricMapsAlignmentAlgorithm.h>

#include "featloc/matchers/MatchResult.h"
#include "featloc/matchers/ScanMatcher.h"

namespace featloc
{
/** Adapter: any featloc ScanMatcher behind MRPT's alignment interface
 * (mrpt::slam::CMetricMapsAlignmentAlgorithm, the one CICP implements), for
 * code written against MRPT.
 *
 * AlignPDF(m1, m2, guess) returns the pose of m2 relative to m1, as CICP
 * does. Both maps must be point maps (mrpt::maps::CPointsMap); their points
 * are sorted by bearing around each map's origin, which is exact for maps
 * built from one scan in its sensor frame. Only planar alignment exists:
 * Align3DPDF throws. */
class ScanMatcherAlignment : public mrpt::slam::CMetricMapsAlignmentAlgorithm
{
   public:
	/** Extra output: the full featloc match result (success flag and
	 * reason, iterations, goodness). */
	struct TReturnInfo : public mrpt::slam::TMetricMapAlignmentResult
	{
		MatchResult match;
	};

	explicit ScanMatcherAlignment(ScanMatcher::Ptr matcher);

	mrpt::poses::CPosePDF::Ptr AlignPDF(
		const mrpt::maps::CMetricMap* m1, const mrpt::maps::CMetricMap* m2,
		const mrpt::poses::CPosePDFGaussian& initialEstimationPDF,
		mrpt::optional_ref<mrpt::slam::TMetricMapAlignmentResult> outInfo =
			std::nullopt) override;

	mrpt::poses::CPose3DPDF::Ptr Align3DPDF(
		const mrpt::maps::CMetricMap* m1, const mrpt::maps::CMetricMap* m2,
		const mrpt::poses::CPose3DPDFGaussian& initialEstimationPDF,
		mrpt::optional_ref<mrpt::slam::TMetricMapAlignmentResult> outInfo =
			std::nullopt) override;

	const ScanMatcher& matcher() const { return *m_matcher; }

   private:
	ScanMatcher::Ptr m_matcher;
};

}  // namespace featloc
