#include "support/StreakFailingIdcMatcher.h"

namespace featloc
{
IMPLEMENTS_MRPT_OBJECT(StreakFailingIdcMatcher, IdcMatcher, featloc)

void StreakFailingIdcMatcher::matchPoints(const ScanPoints& reference,
	const ScanPoints& current, const mrpt::poses::CPosePDFGaussian& initialGuess,
	MatchResult& result)
{
	IdcMatcher::matchPoints(reference, current, initialGuess, result);
	if (m_calls++ >= m_firstFailing)
	{
		result.success = false;
		result.failureReason = "forced failure (test)";
	}
}
}  // namespace featloc
