// ScanPoints::fromScan: a scan's points, and the beam directions it keeps
// from one scan to the next.
#include <gtest/gtest.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <cmath>

#include "featloc/scan/ScanPoints.h"

using namespace featloc;

namespace
{
mrpt::obs::CObservation2DRangeScan scanOf(size_t beams, float aperture, bool rightToLeft)
{
	mrpt::obs::CObservation2DRangeScan s;
	s.aperture = aperture;
	s.rightToLeft = rightToLeft;
	s.maxRange = 30;
	s.resizeScan(beams);
	for (size_t i = 0; i < beams; i++)
	{
		s.setScanRange(i, 1.0f + 0.01f * static_cast<float>(i % 97));
		s.setScanRangeValidity(i, i % 13 != 5);
	}
	s.setScanRange(7, 31.0f);  // beyond maxRange: no return
	return s;
}

/** What fromScan gives, computed beam by beam from MRPT's accessors. */
void expectPointsOf(const mrpt::obs::CObservation2DRangeScan& s)
{
	const ScanPoints p = ScanPoints::fromScan(s);
	std::vector<ScanPoint> want;
	for (size_t i = 0; i < s.getScanSize(); i++)
	{
		if (!ScanPoints::hasReturn(s, i)) continue;
		const double r = s.getScanRange(i), b = s.getScanAngle(i);
		want.push_back({r * std::cos(b), r * std::sin(b), r, b, static_cast<uint32_t>(i)});
	}
	if (!s.rightToLeft) std::reverse(want.begin(), want.end());
	ASSERT_EQ(p.size(), want.size());
	for (size_t k = 0; k < want.size(); k++)
	{
		// Bit for bit: the kept directions are std::cos and std::sin of
		// MRPT's bearings, as computing them for each scan would give.
		EXPECT_EQ(p[k].x, want[k].x);
		EXPECT_EQ(p[k].y, want[k].y);
		EXPECT_EQ(p[k].range, want[k].range);
		EXPECT_EQ(p[k].bearing, want[k].bearing);
		EXPECT_EQ(p[k].beam, want[k].beam);
	}
}
}  // namespace

// Scans of different sensors in turn (beam count, aperture, sweep
// direction): each one's points come from its own beam directions, never
// from those kept for the scan before.
TEST(ScanPoints, EachScansPointsFollowItsOwnBeamGeometry)
{
	const auto sick = scanOf(361, static_cast<float>(M_PI), true);
	const auto wide = scanOf(361, static_cast<float>(1.5 * M_PI), true);
	const auto clockwise = scanOf(361, static_cast<float>(M_PI), false);
	const auto hokuyo = scanOf(1081, static_cast<float>(1.5 * M_PI), true);
	for (int round = 0; round < 2; round++)
		for (const auto* s : {&sick, &wide, &sick, &clockwise, &hokuyo, &sick})
		{
			SCOPED_TRACE(testing::Message() << "beams " << s->getScanSize() << ", aperture "
											<< s->aperture << ", right to left " << s->rightToLeft);
			expectPointsOf(*s);
		}
}
