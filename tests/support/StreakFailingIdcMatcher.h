#pragma once
#include "featloc/matchers/IdcMatcher.h"

namespace featloc
{
/** IDC whose matches all fail from the `firstFailing`-th on (counted from
 * 0): a real matcher run, its result thrown away. A streak of failures,
 * after good matches or from the start, is what the keyframe policy's
 * streak rule (failed_match_keyframe_factor) is tested with. */
class StreakFailingIdcMatcher : public IdcMatcher
{
	DEFINE_MRPT_OBJECT(StreakFailingIdcMatcher, featloc)

   public:
	// One matchPoints() call per match: the iterations run once, from the
	// coarse search (with coarse_confirm_share they may run twice).
	explicit StreakFailingIdcMatcher(size_t firstFailing = 0) : m_firstFailing(firstFailing)
	{
		coarseSearchOptions().confirmShare = 0;
	}

   protected:
	void matchPoints(const ScanPoints& reference, const ScanPoints& current,
		const mrpt::poses::CPosePDFGaussian& initialGuess, MatchResult& result) override;

   private:
	size_t m_firstFailing;
	size_t m_calls = 0;
};
}  // namespace featloc
