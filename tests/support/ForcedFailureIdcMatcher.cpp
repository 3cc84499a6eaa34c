#include "support/ForcedFailureIdcMatcher.h"

namespace featloc
{
IMPLEMENTS_MRPT_OBJECT(ForcedFailureIdcMatcher, IdcMatcher, featloc)

void ForcedFailureIdcMatcher::matchPoints(const ScanPoints& reference,
	const ScanPoints& current, const mrpt::poses::CPosePDFGaussian& initialGuess,
	MatchResult& result)
{
	IdcMatcher::matchPoints(reference, current, initialGuess, result);
	const size_t k = m_calls++;
	if (k >= m_firstFailing && (k - m_firstFailing) % m_period == 0)
	{
		result.success = false;
		result.failureReason = "forced failure (test)";
	}
}
}  // namespace featloc
