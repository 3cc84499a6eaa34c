#pragma once
#include "featloc/matchers/IdcMatcher.h"

namespace featloc
{
/** IDC that reports failure on every other match: a real matcher run, its
 * result thrown away, so the pipeline must carry on with odometry. Failing
 * steps alternate with good ones, which is what the keyframe policy after
 * a failure and the EKF's prediction on a failure are tested with. */
class EveryOtherFailingIdcMatcher : public IdcMatcher
{
	DEFINE_MRPT_OBJECT(EveryOtherFailingIdcMatcher, featloc)

   public:
	// One matchPoints() call per match: the iterations run once, from the
	// coarse search (with coarse_confirm_share they may run twice).
	EveryOtherFailingIdcMatcher() { coarseSearchOptions().confirmShare = 0; }

   protected:
	void matchPoints(const ScanPoints& reference, const ScanPoints& current,
		const mrpt::poses::CPosePDFGaussian& initialGuess, MatchResult& result) override;

   private:
	size_t m_calls = 0;
};
}  // namespace featloc
