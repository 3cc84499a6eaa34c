#pragma once
#include "featloc/matchers/IdcMatcher.h"

namespace featloc
{
/** IDC that reports failure on chosen matches: a real matcher run, its
 * result thrown away, so the pipeline must carry on with odometry. The
 * matches fail from the `firstFailing`-th (counted from 0) on, one in every
 * `period`: everyOther() alternates failing and good steps (the keyframe
 * policy after a failure, the EKF's prediction on a failure), from(n) is a
 * streak from the n-th on (the keyframe policy's streak rule). */
class ForcedFailureIdcMatcher : public IdcMatcher
{
	DEFINE_MRPT_OBJECT(ForcedFailureIdcMatcher, featloc)

   public:
	// One matchPoints() call per match: the iterations run once, from the
	// coarse search (with coarse_confirm_share they may run twice).
	explicit ForcedFailureIdcMatcher(size_t firstFailing = 1, size_t period = 2)
		: m_firstFailing(firstFailing), m_period(period)
	{
		coarseSearchOptions().confirmShare = 0;
	}
	static std::shared_ptr<ForcedFailureIdcMatcher> everyOther()
	{
		return std::make_shared<ForcedFailureIdcMatcher>(1, 2);
	}
	static std::shared_ptr<ForcedFailureIdcMatcher> from(size_t firstFailing)
	{
		return std::make_shared<ForcedFailureIdcMatcher>(firstFailing, 1);
	}

   protected:
	void matchPoints(const ScanPoints& reference, const ScanPoints& current,
		const mrpt::poses::CPosePDFGaussian& initialGuess, MatchResult& result) override;

   private:
	size_t m_firstFailing;
	size_t m_period;
	size_t m_calls = 0;
};
}  // namespace featloc
