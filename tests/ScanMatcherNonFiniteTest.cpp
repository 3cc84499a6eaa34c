// A matcher that reports success with a NaN covariance: ScanMatcher must
// turn it into a failure, not take it as a match. (Found in issue 15's
// twenty-sixth session: a scratch extractor bug gave PCM features with NaN
// covariances, and the confirmation probe slid the estimate along a NaN
// direction for ever; featloc-bench hung.) The matcher below is a fault
// injected on purpose: no real matcher is known to produce NaN, which is
// why the guard is tested this way.
#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <limits>

#include "featloc/math/DiagonalPoseGaussian.h"
#include "featloc/matchers/ScanMatcher.h"
#include "support/SyntheticRoom.h"

using namespace featloc;
using featloc::test::SyntheticRoom;
using mrpt::poses::CPose2D;

namespace
{
/** Succeeds at the guess with a covariance whose first entry is NaN. */
class NanCovarianceMatcher : public ScanMatcher
{
   public:
	mrpt::rtti::CObject* clone() const override { return new NanCovarianceMatcher(*this); }
	int calls = 0;

   protected:
	void loadOwnParams(const mrpt::config::CConfigFileBase&, const std::string&) override {}
	void saveOwnParams(mrpt::config::CConfigFileBase&, const std::string&) const override {}
	void matchPoints(const ScanPoints&, const ScanPoints&,
		const mrpt::poses::CPosePDFGaussian& initialGuess, MatchResult& r) override
	{
		calls++;
		r.success = true;
		r.estimate = initialGuess;
		r.estimate.cov(0, 0) = std::numeric_limits<double>::quiet_NaN();
	}
};
}  // namespace

TEST(ScanMatcher, ASuccessWithANonFiniteCovarianceIsAFailureNotAHang)
{
	const auto s = SyntheticRoom::office().scan(CPose2D(3, 2, 0.2));
	for (const bool coarse : {false, true})
	{
		NanCovarianceMatcher m;
		mrpt::config::CConfigFileMemory c;
		// The coarse search with its confirmation probe out to the window:
		// the probe is where a NaN direction had looped.
		c.setContent(std::string("[S]\ncoarse_search = ") + (coarse ? "true" : "false") +
			"\ncoarse_confirm_probe = true\ncoarse_confirm_probe_window = true\n"
			"coarse_confirm_probe_sigma = 0\n");
		m.loadParams(c, "S");
		const MatchResult r = m.match(*s, *s, diagonalPoseGaussian(CPose2D(), 0.1, 0.1));
		EXPECT_FALSE(r.success);
		EXPECT_EQ(r.failureKind, "non_finite");
		EXPECT_NE(r.failureReason.find("not finite"), std::string::npos) << r.failureReason;
		// With the search, the matcher ran from the guess and from the
		// search's best; both were refused.
		EXPECT_EQ(m.calls, coarse ? 2 : 1);
	}
}
