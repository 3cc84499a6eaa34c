#include <gtest/gtest.h>
#include <mrpt/core/bits_math.h>
#include <mrpt/random/RandomGenerators.h>

#include <cmath>
#include <map>
#include <numeric>

#include "featloc/features/CurvatureFunction.h"
#include "featloc/features/CurvatureFunctionMatcher.h"
#include "featloc/scan/AdaptiveBreakpointSegmenter.h"
#include "support/SyntheticRoom.h"

using namespace featloc;

namespace
{
/** The points where beams from the origin at `bearingsDeg` hit the line
 * through (x0, y0) with direction (dx, dy): noise-free scan points. */
void addLine(ScanPoints& s, double x0, double y0, double dx, double dy,
	const std::vector<double>& bearingsDeg)
{
	for (double deg : bearingsDeg)
	{
		const double b = mrpt::DEG2RAD(deg), ux = std::cos(b), uy = std::sin(b);
		// origin + r u = p0 + t d
		const double den = ux * dy - uy * dx;
		const double r = (x0 * dy - y0 * dx) / den;
		ScanPoint p;
		p.range = r;
		p.bearing = b;
		p.x = r * ux;
		p.y = r * uy;
		s.points.push_back(p);
	}
}

std::vector<double> degrees(double from, double to, double step)
{
	std::vector<double> out;
	for (double d = from; d <= to + 1e-9; d += step) out.push_back(d);
	return out;
}

/** Points every `step` metres along a polyline (its corners included). */
ScanPoints polyline(const std::vector<std::pair<double, double>>& corners, double step)
{
	ScanPoints s;
	for (size_t k = 0; k + 1 < corners.size(); k++)
	{
		const auto [x0, y0] = corners[k];
		const auto [x1, y1] = corners[k + 1];
		const double len = std::hypot(x1 - x0, y1 - y0);
		const int n = static_cast<int>(std::round(len / step));
		for (int i = (k == 0 ? 0 : 1); i <= n; i++)
		{
			ScanPoint p;
			p.x = x0 + (x1 - x0) * i / n;
			p.y = y0 + (y1 - y0) * i / n;
			p.range = std::hypot(p.x, p.y);
			p.bearing = std::atan2(p.y, p.x);
			s.points.push_back(p);
		}
	}
	return s;
}

ScanSegment all(const ScanPoints& s) { return {0, static_cast<uint32_t>(s.size() - 1)}; }
}  // namespace

TEST(AdaptiveBreakpointSegmenter, AJumpIsABreakAndASmoothWallIsNot)
{
	// A wall 3 m ahead (y = 3) from 60 to 120 deg, then a wall 5 m ahead
	// from 120.5 to 150 deg: one depth jump.
	ScanPoints s;
	addLine(s, 0, 3, 1, 0, degrees(60, 120, 0.5));
	addLine(s, 0, 5, 1, 0, degrees(120.5, 150, 0.5));
	std::vector<ScanSegment> segments;
	AdaptiveBreakpointSegmenter().segment(s, segments);
	ASSERT_EQ(segments.size(), 2u);
	EXPECT_EQ(segments[0].first, 0u);
	EXPECT_EQ(segments[0].last, 120u);	// the last point at 120 deg
	EXPECT_EQ(segments[1].first, 121u);
	EXPECT_EQ(segments[1].last, s.size() - 1);
}

TEST(AdaptiveBreakpointSegmenter, ADenseNoisyWallIsOneSegmentWithSigmaFromTheScan)
{
	// One wall 1 m ahead, 1081 beams over 270 deg, 3 cm range noise: with
	// the paper's fixed 5 mm sigma_r, eq. (3) breaks it wherever two
	// neighbours differ by some 4 cm in range; with sigma_r estimated from
	// the scan (about 3 cm), the wall stays whole.
	featloc::test::SyntheticRoom wall;
	wall.add(1, -20, 1, 20);
	mrpt::random::CRandomGenerator rng(7);
	auto scan = wall.scan(mrpt::poses::CPose2D(), mrpt::poses::CPose2D(), 1081, mrpt::DEG2RAD(270.0));
	for (size_t i = 0; i < scan->getScanSize(); i++)
		if (scan->getScanRangeValidity(i))
			scan->setScanRange(i,
				scan->getScanRange(i) + static_cast<float>(0.03 * rng.drawGaussian1D_normalized()));
	const ScanPoints s = ScanPoints::fromScan(*scan);
	// Within 60 deg of the wall's normal: a few points further out are
	// far apart anyway.
	auto segmentsNearTheNormal = [&](bool fromScan, double* sigma) {
		AdaptiveBreakpointSegmenter::Parameters p;
		p.sigmaFromScan = fromScan;
		const AdaptiveBreakpointSegmenter seg(p);
		std::vector<ScanSegment> out;
		seg.segment(s, out);
		*sigma = seg.lastSigmaR();
		size_t n = 0;
		for (const auto& g : out)
			n += std::abs(s.points[g.first].bearing) < mrpt::DEG2RAD(60.0);
		return n;
	};
	double fixed = 0, estimated = 0;
	EXPECT_GT(segmentsNearTheNormal(false, &fixed), 50u);
	EXPECT_EQ(fixed, 0.005);
	EXPECT_LE(segmentsNearTheNormal(true, &estimated), 3u);
	EXPECT_NEAR(estimated, 0.03, 0.006);
}

TEST(AdaptiveBreakpointSegmenter, IncidenceAboveLambdaBreaksAWall)
{
	// Eq. (3): a wall seen at 75 deg incidence (below 90 - lambda = 80) is
	// continuous; at 87 deg its points are farther apart than the bound.
	const AdaptiveBreakpointSegmenter seg;
	auto pairAtIncidence = [](double incidenceDeg) {
		// Wall through (3, 0) whose normal makes `incidenceDeg` with the beam
		// at bearing 0; two beams 0.5 deg apart.
		const double a = mrpt::DEG2RAD(incidenceDeg);
		ScanPoints s;
		addLine(s, 3, 0, std::sin(a), std::cos(a), {0.0, 0.5});
		return s;
	};
	const ScanPoints ok = pairAtIncidence(75), grazing = pairAtIncidence(87);
	EXPECT_FALSE(seg.isBreakpoint(ok[0], ok[1]));
	EXPECT_TRUE(seg.isBreakpoint(grazing[0], grazing[1]));
	// A gap wider than lambda (a sector of missing returns) always breaks.
	ScanPoints gap;
	addLine(gap, 0, 3, 1, 0, {80.0, 91.0});
	EXPECT_TRUE(seg.isBreakpoint(gap[0], gap[1]));
}

TEST(CurvatureFunction, AStraightWallHasNoCurvature)
{
	const ScanPoints s = polyline({{-2, 3}, {2, 3}}, 0.05);
	for (const std::string sampling : {"metric", "normalized"})
	{
		CurvatureFunction cf;
		cf.params.sampling = sampling;
		std::vector<double> eta;
		cf.compute(s, all(s), eta);
		ASSERT_FALSE(eta.empty());
		for (double v : eta) EXPECT_NEAR(v, 0, 1e-12) << sampling;
		// eq. (4): on a straight wall nothing bends, so every window reaches
		// the end of the segment.
		for (size_t i = 0; i + 1 < s.size(); i++)
			EXPECT_EQ(cf.lastWindows()[i], s.size() - 1 - i);
	}
	CurvatureFunction metric;
	std::vector<double> eta;
	metric.compute(s, all(s), eta);
	EXPECT_EQ(eta.size(), 40u);	 // 4 m at curvature_step 0.1 m
}

TEST(CurvatureFunction, ACornerTurnsByItsAngleNearTheCorner)
{
	// 2 m of wall, a right-angle corner, 2 m of wall, U_k = 5 cm: a window
	// ends about 5 cm past the corner (eq. 4), so a point a metres before it
	// looks atan(0.05 / a) round the corner: the function peaks at the
	// corner and falls off as 1/a^2 away from it.
	const ScanPoints s = polyline({{2, 1}, {2, 3}, {0, 3}}, 0.05);
	CurvatureFunction cf;
	cf.params.U_k = 0.05;
	std::vector<double> eta;
	cf.compute(s, all(s), eta);
	ASSERT_EQ(eta.size(), 40u);
	size_t peak = 0;
	for (size_t k = 0; k < eta.size(); k++)
		if (std::abs(eta[k]) > std::abs(eta[peak])) peak = k;
	EXPECT_TRUE(peak == 19 || peak == 20) << peak;	// the corner is 2 m along
	EXPECT_GT(std::abs(eta[peak]), 1.0);
	// Away from the corner: d/ds atan(0.05 / a) over a 0.1 m sample is
	// about 0.005 / a^2 (a: distance to the corner); twice that at most.
	for (size_t k = 0; k < eta.size(); k++)
	{
		const double s0 = 0.1 * static_cast<double>(k), s1 = s0 + 0.1;
		const double a = std::min(std::abs(2 - s0), std::abs(2 - s1));
		if (a >= 0.3)
		{
			EXPECT_LT(std::abs(eta[k]), 0.01 / (a * a)) << "sample " << k;
		}
	}
	// The first chord already leans atan(0.05 / 2) round the corner; the
	// last one is along the second wall: the total turn is the rest.
	const auto& th = cf.lastDirections();
	EXPECT_NEAR(th.front(), M_PI / 2 + std::atan(0.05 / 2), 1e-3);
	EXPECT_NEAR(th.back(), M_PI, 1e-9);
	const double turn = std::accumulate(eta.begin(), eta.end(), 0.0);
	EXPECT_NEAR(turn, th.back() - th.front(), 1e-9);
}

namespace
{
/** The documented similarity, computed directly (no FFT). */
double directSimilarity(
	const std::vector<double>& c, const std::vector<double>& r, bool circular, double e, int* shift)
{
	const double e2 = e * e;
	double best = -1e300;
	if (circular)
	{
		const size_t L = c.size();
		double nc = 0, nr = 0;
		for (size_t k = 0; k < L; k++) nc += c[k] * c[k], nr += r[k] * r[k];
		const double den = std::sqrt((nc + e2 * L) * (nr + e2 * L));
		for (size_t s = 0; s < L; s++)
		{
			double corr = 0;
			for (size_t k = 0; k < L; k++) corr += c[k] * r[(k + s) % L];
			const double v = (corr + e2 * L) / den;
			if (v > best) best = v, *shift = static_cast<int>(s);
		}
		return best;
	}
	const int nc = static_cast<int>(c.size()), nr = static_cast<int>(r.size());
	const double minOverlap = std::max(2.0, 0.5 * std::min(nc, nr)) - 0.5;
	for (int s = -nc + 1; s < nr; s++)
	{
		double corr = 0, ec = 0, er = 0, n = 0;
		for (int k = 0; k < nc; k++)
		{
			const int j = k + s;
			if (j < 0 || j >= nr) continue;
			corr += c[k] * r[j];
			ec += c[k] * c[k];
			er += r[j] * r[j];
			n++;
		}
		if (n < minOverlap) continue;
		const double v = (corr + e2 * n) / std::sqrt((ec + e2 * n) * (er + e2 * n));
		if (v > best) best = v, *shift = s;
	}
	return best;
}
}  // namespace

TEST(CurvatureFunctionMatcher, FftSimilarityEqualsTheDirectCorrelation)
{
	mrpt::random::CRandomGenerator rng(5);
	auto randomFunction = [&](size_t n) {
		std::vector<double> f(n);
		for (auto& v : f) v = rng.drawGaussian1D_normalized() * 0.1;
		return f;
	};
	CurvatureFunctionMatcher m;
	const double e = m.params.curvature_floor;
	// Circular: one power-of-two length, as the paper.
	std::vector<std::vector<double>> c{randomFunction(64), randomFunction(64)};
	std::vector<std::vector<double>> r{randomFunction(64), randomFunction(64), randomFunction(64)};
	std::vector<CurvatureFunctionMatcher::Match> out;
	m.match(c, r, std::vector<char>(6, 1), true, out);
	for (size_t i = 0; i < c.size(); i++)
		for (size_t j = 0; j < r.size(); j++)
		{
			int shift = 0;
			const double direct = directSimilarity(c[i], r[j], true, e, &shift);
			EXPECT_NEAR(m.lastSimilarity()[i * r.size() + j], direct, 1e-9);
			EXPECT_EQ(m.lastShift()[i * r.size() + j], shift);
		}
	// Linear: different lengths, normalised over the overlap.
	c = {randomFunction(37), randomFunction(12)};
	r = {randomFunction(50), randomFunction(9), randomFunction(23)};
	m.match(c, r, std::vector<char>(6, 1), false, out);
	for (size_t i = 0; i < c.size(); i++)
		for (size_t j = 0; j < r.size(); j++)
		{
			int shift = 0;
			const double direct = directSimilarity(c[i], r[j], false, e, &shift);
			EXPECT_NEAR(m.lastSimilarity()[i * r.size() + j], std::max(0.0, direct), 1e-9);
			EXPECT_EQ(m.lastShift()[i * r.size() + j], shift);
		}
}

TEST(CurvatureFunctionMatcher, IdenticalShapesGiveOneAtTheirShift)
{
	mrpt::random::CRandomGenerator rng(8);
	std::vector<double> f(64);
	for (auto& v : f) v = rng.drawGaussian1D_normalized() * 0.2;
	std::vector<double> shifted(64);
	for (size_t k = 0; k < 64; k++) shifted[(k + 9) % 64] = f[k];
	CurvatureFunctionMatcher m;
	std::vector<CurvatureFunctionMatcher::Match> out;
	m.match({f}, {shifted}, out);  // one power-of-two length: circular
	ASSERT_EQ(out.size(), 1u);
	EXPECT_NEAR(out[0].similarity, 1.0, 1e-12);
	EXPECT_EQ(out[0].shift, 9);

	// A wall seen further along (metric sampling): the same samples where
	// both see it.
	std::vector<double> wall(40, 0.0);
	wall[30] = 0.8;	 // a corner 3 m along
	const std::vector<double> later(wall.begin() + 10, wall.end());	 // its last 3 m
	m.match({later}, {wall}, out);
	ASSERT_EQ(out.size(), 1u);
	EXPECT_NEAR(out[0].similarity, 1.0, 1e-12);
	EXPECT_EQ(out[0].shift, 10);
}

TEST(CurvatureFunctionMatcher, GreedyPairingTakesTheMostSimilarAboveUc)
{
	// Reference: a straight piece, a corner, an S-bend; current: the S-bend,
	// the corner, and a zig-zag that is like nothing in the reference.
	std::vector<double> straight(32, 0.0), corner(32, 0.0), sbend(32, 0.0), zigzag(32, 0.0);
	corner[16] = M_PI / 2;
	sbend[8] = 0.6;
	sbend[24] = -0.6;
	for (size_t k = 0; k < 32; k += 2) zigzag[k] = (k % 4 == 0 ? 0.5 : -0.5);
	CurvatureFunctionMatcher m;
	std::vector<CurvatureFunctionMatcher::Match> out;
	m.match({sbend, corner, zigzag}, {straight, corner, sbend}, out);
	ASSERT_EQ(out.size(), 2u);
	EXPECT_EQ(out[0].current, 0u);	// identical pairs first
	EXPECT_EQ(out[0].reference, 2u);
	EXPECT_EQ(out[1].current, 1u);
	EXPECT_EQ(out[1].reference, 1u);
	for (size_t j = 0; j < 3; j++) EXPECT_LT(m.lastSimilarity()[2 * 3 + j], m.params.U_c);
	// A straight piece is like a straight piece, not like a corner.
	m.match({straight}, {straight, corner}, out);
	EXPECT_NEAR(m.lastSimilarity()[0], 1.0, 1e-12);
	EXPECT_LT(m.lastSimilarity()[1], 0.1);
}

// At the default U_k = 1.0 m (the paper's value read in metres) a clean
// right-angle corner between 2 m walls shows no peak: a window from a point
// a metres before the corner reaches b past it, a + b - sqrt(a^2 + b^2) = 1,
// so the chord already leans round the corner 2 m before it, and the 90 deg
// turn is spread over those 2 m; past the corner nothing turns.
TEST(CurvatureFunction, AtTheDefaultUkACornerIsARampNotAPeak)
{
	const ScanPoints s = polyline({{2, 1}, {2, 3}, {0, 3}}, 0.05);
	CurvatureFunction cf;
	ASSERT_EQ(cf.params.U_k, 1.0);
	std::vector<double> eta;
	cf.compute(s, all(s), eta);
	ASSERT_EQ(eta.size(), 40u);
	double before = 0, after = 0, peak = 0;
	for (size_t k = 0; k < eta.size(); k++)
	{
		(k < 20 ? before : after) += eta[k];
		peak = std::max(peak, std::abs(eta[k]));
	}
	// The first chord leans atan(1.5 / 2) = 36.9 deg (b = 1.5 m for a = 2 m).
	EXPECT_NEAR(cf.lastDirections().front(), M_PI / 2 + std::atan(1.5 / 2), 0.02);
	EXPECT_NEAR(before, M_PI / 2 - std::atan(1.5 / 2), 0.02);
	EXPECT_NEAR(after, 0, 1e-9);
	EXPECT_LT(peak, mrpt::DEG2RAD(5.0));  // no sample turns by more than 5 deg
}

// The paper's own calibration of U_k (section IV.A: planes scanned at
// several distances; U_k is set so that they show no local peak), on
// featloc's SICK LMS200 model (361 beams over 180 deg, 1 cm noise): the
// largest |eta| inside noisy 3 m planes at 1-6 m, straight on and at 45 deg
// (20 scans each; the last 0.5 m left out, where windows cannot grow),
// against the peak of a clean corner. Only the literal reading, 1.0 m, comes
// near "no peak on a plane", and there a corner barely stands out: the
// curvature function cannot tell much apart at this noise (doc/benchmarks.md,
// the CF-IDC ablation). The table is printed for the doc.
TEST(CurvatureFunction, ThePapersCalibrationOfUkOnASickModel)
{
	mrpt::random::CRandomGenerator rng(9);
	std::map<double, std::pair<double, double>> planeAndCorner;
	for (double U : {0.01, 0.05, 0.1, 0.2, 0.5, 1.0})
	{
		double worst = 0;
		for (double d : {1.0, 2.0, 4.0, 6.0})
			for (double incidence : {0.0, 45.0})
			{
				featloc::test::SyntheticRoom plane;
				const double a = mrpt::DEG2RAD(incidence);
				const double tx = -std::sin(a), ty = std::cos(a);
				plane.add(d - 1.5 * tx, -1.5 * ty, d + 1.5 * tx, 1.5 * ty);
				for (int trial = 0; trial < 20; trial++)
				{
					auto sc = plane.scan(mrpt::poses::CPose2D(), mrpt::poses::CPose2D(), 361, M_PI);
					for (size_t i = 0; i < sc->getScanSize(); i++)
						if (sc->getScanRangeValidity(i))
							sc->setScanRange(i, sc->getScanRange(i) +
									static_cast<float>(0.01 * rng.drawGaussian1D_normalized()));
					const ScanPoints pts = ScanPoints::fromScan(*sc);
					CurvatureFunction cf;
					cf.params.U_k = U;
					std::vector<double> eta;
					cf.compute(pts, all(pts), eta);
					for (size_t k = 0; k + 5 < eta.size(); k++)
						worst = std::max(worst, std::abs(eta[k]));
				}
			}
		const ScanPoints corner = polyline({{2, 1}, {2, 3}, {0, 3}}, 0.05);
		CurvatureFunction cf;
		cf.params.U_k = U;
		std::vector<double> eta;
		cf.compute(corner, all(corner), eta);
		double peak = 0;
		for (double v : eta) peak = std::max(peak, std::abs(v));
		planeAndCorner[U] = {mrpt::RAD2DEG(worst), mrpt::RAD2DEG(peak)};
		std::printf("| %.2f m | %.1f | %.1f |\n", U, mrpt::RAD2DEG(worst), mrpt::RAD2DEG(peak));
	}
	// Centimetre windows: the noise turns more than a corner does.
	for (double U : {0.01, 0.05})
		EXPECT_GT(planeAndCorner[U].first, planeAndCorner[U].second) << "U_k " << U;
	// The planes flatten as U_k grows, the flattest at the literal value,
	// an order of magnitude below centimetre windows...
	double previous = 1e300;
	for (const auto& [U, pc] : planeAndCorner)
	{
		EXPECT_LT(pc.first, previous) << "U_k " << U;
		previous = pc.first;
	}
	EXPECT_LT(planeAndCorner[1.0].first, planeAndCorner[0.01].first / 10);
	// ...and there a corner hardly stands out of them.
	EXPECT_LT(planeAndCorner[1.0].second, 2 * planeAndCorner[1.0].first);
}
