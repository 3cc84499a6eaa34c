#include "support/EveryOtherFailingIdcMatcher.h"

namespace featloc
{
IMPLEMENTS_MRPT_OBJECT(EveryOtherFailingIdcMatcher, IdcMatcher, featloc)

void EveryOtherFailingIdcMatcher::matchPoints(const ScanPoints& reference,
	const ScanPoints& current, const mrpt::poses::CPosePDFGaussian& initialGuess,
	MatchResult& result)
{
	IdcMatcher::matchPoints(reference, current, initialGuess, result);
	if (m_calls++ % 2 == 1)
	{
		result.success = false;
		result.failureReason = "forced failure (test)";
	}
}
}  // namespace featloc
