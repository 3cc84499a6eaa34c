// PCM's features extracted once per scan (LineEllipseExtractor's memo).
#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/random/RandomGenerators.h>

#include "featloc/features/LineEllipseExtractor.h"
#include "featloc/math/DiagonalPoseGaussian.h"
#include "featloc/scan/ScanPoints.h"
#include "support/MatcherTestHelpers.h"
#include "support/SyntheticRoom.h"

using namespace featloc;
using featloc::test::SyntheticRoom;
using mrpt::poses::CPose2D;

// PCM extracts each scan's features once when it matches consecutive scans:
// the reference's are those of the previous pair's current scan. The result
// must be the same, bit for bit, as a fresh matcher's.
TEST(LineEllipseExtractorMemo, ConsecutivePairsGiveTheSameMatchesAsFreshMatchers)
{
	const SyntheticRoom office = SyntheticRoom::office();
	mrpt::random::CRandomGenerator rng(7);
	const auto a = featloc::test::withRangeNoise(office.scan(CPose2D(0, 0, 0)), rng, 0.01);
	const auto b = featloc::test::withRangeNoise(office.scan(CPose2D(0.1, 0.02, 0.02)), rng, 0.01);
	const auto c = featloc::test::withRangeNoise(office.scan(CPose2D(0.2, 0.03, 0.05)), rng, 0.01);
	const auto guess = diagonalPoseGaussian(CPose2D(0.1, 0, 0.02), 0.05, 0.02);
	auto sequential = featloc::test::configuredMatcher("featloc::PcmFeatureMatcher");
	sequential->match(*a, *b, guess);
	const MatchResult second = sequential->match(*b, *c, guess);
	auto fresh = featloc::test::configuredMatcher("featloc::PcmFeatureMatcher");
	const MatchResult alone = fresh->match(*b, *c, guess);
	ASSERT_TRUE(alone.success) << alone.failureReason;
	EXPECT_EQ(second.estimate.mean.x(), alone.estimate.mean.x());
	EXPECT_EQ(second.estimate.mean.y(), alone.estimate.mean.y());
	EXPECT_EQ(second.estimate.mean.phi(), alone.estimate.mean.phi());
	EXPECT_EQ(second.estimate.cov, alone.estimate.cov);
	EXPECT_EQ(second.iterations, alone.iterations);
}

TEST(LineEllipseExtractorMemo, NewParametersOrOtherPointsExtractAnew)
{
	const SyntheticRoom office = SyntheticRoom::office();
	const ScanPoints s = ScanPoints::fromScan(*office.scan(CPose2D(0, 0, 0)));
	LineEllipseExtractor x;
	std::vector<ScanFeature> first, again;
	x.extract(s, first);
	ASSERT_GT(first.size(), 3u);
	x.extract(s, again);
	EXPECT_EQ(again.size(), first.size());
	// Parameters changed after the memo was taken: no line is that long.
	x.params.min_length = 100;
	x.params.ellipse_max_length = 0;
	std::vector<ScanFeature> none;
	x.extract(s, none);
	EXPECT_TRUE(none.empty());
	// The line fit changed: the memo (which once left line_fit out of its
	// comparison) must not give the weighted fit's lines back.
	x.params = LineEllipseExtractor::Parameters();
	x.extract(s, again);
	x.params.line_fit = "tls";
	std::vector<ScanFeature> tls;
	x.extract(s, tls);
	ASSERT_EQ(tls.size(), again.size());
	bool fitDiffers = false;
	for (size_t i = 0; i < tls.size(); i++) fitDiffers |= tls[i].varAlpha != again[i].varAlpha;
	EXPECT_TRUE(fitDiffers);
	// One point moved by a micrometre: another scan.
	x.params = LineEllipseExtractor::Parameters();
	ScanPoints moved = s;
	moved.points[10].x += 1e-6;
	EXPECT_FALSE(moved.samePointsAs(s));
	EXPECT_TRUE(s.samePointsAs(ScanPoints(s)));
	std::vector<ScanFeature> other;
	x.extract(moved, other);
	ASSERT_EQ(other.size(), first.size());
	bool anyDiffers = false;
	for (size_t i = 0; i < other.size(); i++)
		anyDiffers |= other[i].x != first[i].x ||
			other[i].y != first[i].y || other[i].rho != first[i].rho;
	EXPECT_TRUE(anyDiffers);
}
