// Borges & Aldon feature extraction and the quartic solver.
#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/core/bits_math.h>
#include <mrpt/math/wrap2pi.h>
#include <mrpt/random/RandomGenerators.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>

#include "featloc/core/ConfigError.h"
#include "featloc/features/LineEllipseExtractor.h"
#include "featloc/features/LineFit.h"
#include "featloc/math/PolynomialRoots.h"
#include "support/ErrorMessage.h"
#include "support/SyntheticRoom.h"

using namespace featloc;
using featloc::test::SyntheticRoom;
using mrpt::poses::CPose2D;

namespace
{
ScanPoints pointsOn(double rho, double alpha, double s0, double s1, size_t n, double noise,
	mrpt::random::CRandomGenerator& rng)
{
	ScanPoints out;
	const double ca = std::cos(alpha), sa = std::sin(alpha);
	for (size_t k = 0; k < n; k++)
	{
		const double s = s0 + (s1 - s0) * static_cast<double>(k) / static_cast<double>(n - 1);
		const double e = noise * rng.drawGaussian1D_normalized();
		ScanPoint p;
		p.x = (rho + e) * ca - s * sa;
		p.y = (rho + e) * sa + s * ca;
		p.range = std::hypot(p.x, p.y);
		p.bearing = std::atan2(p.y, p.x);
		out.points.push_back(p);
	}
	return out;
}

/** A scan of a wall parallel to the x axis at y = wallYAt(bearing), from
 * bearing `from` to `to` [rad] every `step`, with Gaussian range noise. */
ScanPoints wallScan(double from, double to, double step, double sigma,
	mrpt::random::CRandomGenerator& rng, const std::function<double(double)>& wallYAt)
{
	ScanPoints s;
	s.angularStep = step;
	s.maxRange = 30;
	for (double b = from; b <= to; b += step)
	{
		const double r = wallYAt(b) / std::sin(b) + sigma * rng.drawGaussian1D_normalized();
		ScanPoint p;
		p.range = r;
		p.bearing = b;
		p.x = r * std::cos(b);
		p.y = r * std::sin(b);
		p.beam = static_cast<uint32_t>(s.points.size());
		s.points.push_back(p);
	}
	return s;
}

/** A scan of a rack's face at y = 1.3 m seen from (sensorX, 0), 0.25 deg
 * beams from x = 9 m to x = -3 m along it, 1 cm range noise: uprights 10 cm
 * wide standing `depth` out of the face every 2.7 m (x = 2.7 k - 10), their
 * sides ray-cast as well as their fronts, and optionally a pallet pushed
 * 15 cm out of its bay between x = 3.5 and 4.7 (in the world). `hit` gets,
 * per beam, 0 for the face, 1 for an upright or the pallet. */
ScanPoints rackFaceScan(double sensorX, double depth, bool pallet,
	mrpt::random::CRandomGenerator& rng, std::vector<int>& hit)
{
	ScanPoints s;
	s.angularStep = mrpt::DEG2RAD(0.25);
	s.maxRange = 30;
	hit.clear();
	// Axis-aligned boxes in the sensor frame: [x0, x1] x [y0, 1.3].
	std::vector<std::array<double, 3>> boxes;
	for (double x0 = -10.0; x0 < 20; x0 += 2.7)
		boxes.push_back({x0 - sensorX, x0 + 0.1 - sensorX, 1.3 - depth});
	if (pallet) boxes.push_back({3.5 - sensorX, 4.7 - sensorX, 1.15});
	for (double b = std::atan2(1.3, 9.0); b <= std::atan2(1.3, -3.0); b += s.angularStep)
	{
		const double c = std::cos(b), sn = std::sin(b);
		double t = 1.3 / sn;
		int what = 0;
		for (const auto& [x0, x1, y0] : boxes)
		{
			if (!(y0 < 1.3)) continue;
			const double tf = y0 / sn, xf = tf * c;  // the box's front
			if (xf >= x0 && xf <= x1 && tf < t) t = tf, what = 1;
			for (double xs : {x0, x1})	// its sides
			{
				if (std::abs(c) < 1e-9) continue;
				const double ts = xs / c, ys = ts * sn;
				if (ts > 0 && ys >= y0 && ys <= 1.3 && ts < t) t = ts, what = 1;
			}
		}
		const double r = t + 0.01 * rng.drawGaussian1D_normalized();
		ScanPoint p;
		p.range = r;
		p.bearing = b;
		p.x = r * c;
		p.y = r * sn;
		p.beam = static_cast<uint32_t>(s.points.size());
		s.points.push_back(p);
		hit.push_back(what);
	}
	return s;
}
}  // namespace

TEST(LineFit, ExactOnCollinearPointsAndSigmaIsTheResidualRms)
{
	mrpt::random::CRandomGenerator rng(1);
	const auto exact = pointsOn(2.5, 0.7, -1, 1, 50, 0, rng);
	const LineFit f = LineFit::fit(exact.points.data(), exact.size());
	EXPECT_NEAR(f.rho, 2.5, 1e-12);
	EXPECT_NEAR(f.alpha, 0.7, 1e-12);
	EXPECT_NEAR(f.sigma, 0, 1e-12);
	EXPECT_NEAR(f.length, 2.0, 1e-12);
	// A line behind the origin still gets rho >= 0 (alpha flipped).
	const auto behind = pointsOn(-1.5, 0.3, -1, 1, 20, 0, rng);
	const LineFit g = LineFit::fit(behind.points.data(), behind.size());
	EXPECT_NEAR(g.rho, 1.5, 1e-12);
	EXPECT_NEAR(std::cos(g.alpha), -std::cos(0.3), 1e-12);
	// Noise: sigma estimates it (eq. 8), alpha within its predicted spread.
	const auto noisy = pointsOn(3, -1.2, -2, 2, 400, 0.01, rng);
	const LineFit h = LineFit::fit(noisy.points.data(), noisy.size());
	EXPECT_NEAR(h.sigma, 0.01, 0.0015);
	EXPECT_LT(std::abs(h.alpha + 1.2), 4 * 0.01 / std::sqrt(h.sumS2));
}

TEST(LineEllipseExtractor, RoomWallsBecomeLinesAndSmallObjectsEllipses)
{
	SyntheticRoom room;
	room.add(-4, -3, 4, -3);  // walls: rho = 3 at alpha = -90 deg, ...
	room.add(4, -3, 4, 3);
	room.add(4, 3, -4, 3);
	room.add(-4, 3, -4, -3);
	room.add(2.0, 1.0, 2.4, 1.0);  // a 0.4 m box side facing the sensor
	room.add(-1.0, -1.5, -0.9, -1.5);  // a 0.1 m stub: too short for anything
	const auto scan = room.scan(CPose2D(), CPose2D(), 721, 2 * M_PI - 0.01, 30);
	LineEllipseExtractor ex;
	std::vector<ScanFeature> fs;
	ex.extract(ScanPoints::fromScan(*scan), fs);

	// Every line is one of the four walls (a wall cut by an occluder or by
	// the scan's seam gives several lines, all with its parameters); every
	// wall is found; the 0.4 m box side is the one ellipsoidal cluster and
	// the 0.1 m stub gives nothing.
	const std::vector<std::pair<double, double>> walls = {
		{3, -M_PI / 2}, {4, 0}, {3, M_PI / 2}, {4, M_PI}};
	std::vector<int> found(walls.size(), 0);
	size_t ellipses = 0;
	for (const auto& f : fs)
	{
		if (f.kind == ScanFeature::Kind::Ellipse)
		{
			ellipses++;
			// The box side seen from the origin: centroid of its samples
			// (denser towards the near end, hence below the middle 2.2).
			EXPECT_NEAR(f.y, 1.0, 1e-6);
			EXPECT_NEAR(f.x, 2.2, 0.03);
			EXPECT_EQ(f.a2, 1);
			EXPECT_EQ(f.c, 0);
			continue;
		}
		bool isWall = false;
		for (size_t w = 0; w < walls.size(); w++)
		{
			const auto [rho, alpha] = walls[w];
			if (std::abs(f.rho - rho) > 1e-5 || std::cos(f.alpha - alpha) < 1 - 1e-9) continue;
			// Scans store ranges as floats: exact to ~1e-7 relative.
			EXPECT_NEAR(f.a2, std::cos(alpha) * std::cos(alpha), 1e-6);
			EXPECT_NEAR(f.x, rho * std::cos(alpha), 1e-5);
			EXPECT_NEAR(f.y, rho * std::sin(alpha), 1e-5);
			EXPECT_GT(f.length, 0.5);
			found[w]++;
			isWall = true;
		}
		EXPECT_TRUE(isWall) << "line rho " << f.rho << " alpha " << f.alpha;
	}
	for (size_t w = 0; w < walls.size(); w++) EXPECT_GE(found[w], 1) << "wall " << w;
	EXPECT_EQ(ellipses, 1u);
}

TEST(LineEllipseExtractor, NoisyLinesAndGapsAndClutter)
{
	mrpt::random::CRandomGenerator rng(3);
	ScanPoints s = pointsOn(2.0, 0.0, -1.5, 1.5, 120, 0.01, rng);  // a wall
	// A leg-like blob: 3 points, far from the wall (a gap > 0.5 m).
	for (double dy : {0.0, 0.03, 0.06})
	{
		ScanPoint p;
		p.x = 0.8;
		p.y = 2.0 + dy;
		s.points.push_back(p);
	}
	LineEllipseExtractor ex;
	std::vector<ScanFeature> fs;
	ex.extract(s, fs);
	ASSERT_EQ(fs.size(), 1u);  // the blob has fewer than min_points
	EXPECT_EQ(fs[0].kind, ScanFeature::Kind::Line);
	EXPECT_NEAR(fs[0].rho, 2.0, 0.005);
	EXPECT_NEAR(fs[0].sigma, 0.01, 0.003);
	// The covariance of the foot point: var(rho) along the normal.
	EXPECT_NEAR(std::sqrt(fs[0].cxx), 0.01 / std::sqrt(120.0), 0.0006);
	// Too noisy for a line: rejected (sigma > max_line_sigma).
	ScanPoints rough = pointsOn(2.0, 0.0, -1.5, 1.5, 120, 0.12, rng);
	ex.params.split_distance_min = 10;	// do not split, test the sigma gate
	ex.extract(rough, fs);
	EXPECT_TRUE(fs.empty());
}

TEST(PolynomialRoots, KnownRoots)
{
	// (z - 0.5)(z + 0.3)(z - 2)(z - 0.9) = z^4 - 3.1 z^3 + 2.23 z^2 + 0.075 z - 0.27
	auto r = PolynomialRoots::real({-0.27, 0.075, 2.23, -3.1, 1});
	ASSERT_EQ(r.size(), 4u);
	EXPECT_NEAR(r[0], -0.3, 1e-10);
	EXPECT_NEAR(r[1], 0.5, 1e-10);
	EXPECT_NEAR(r[2], 0.9, 1e-10);
	EXPECT_NEAR(r[3], 2.0, 1e-10);
	// (z^2 + 1)(z - 0.25): one real root.
	r = PolynomialRoots::real({-0.25, 1, -0.25, 1, 0});
	ASSERT_EQ(r.size(), 1u);
	EXPECT_NEAR(r[0], 0.25, 1e-12);
	// Degree drops when leading coefficients vanish; zero polynomial: none.
	r = PolynomialRoots::real({-2, 4, 0, 0, 0});
	ASSERT_EQ(r.size(), 1u);
	EXPECT_NEAR(r[0], 0.5, 1e-15);
	EXPECT_TRUE(PolynomialRoots::real({0, 0, 0, 0, 0}).empty());
	// A double root is reported once.
	r = PolynomialRoots::real({0.25, -1, 1});
	ASSERT_EQ(r.size(), 1u);
	EXPECT_NEAR(r[0], 0.5, 1e-6);
}

// A wall seen from near its foot out to grazing incidence, with range noise
// only (along each beam): its far points lie much closer to the line than
// its near ones. The weighted fit (line_fit = weighted, the maximum
// likelihood line) gives the orientation with a smaller spread than the
// unweighted fit of eqs. (3)-(8), and each fit's predicted variance is its
// actual spread over many scans.
TEST(LineEllipseExtractor, WeightedFitUsesTheGrazingPointsAndItsCovarianceHolds)
{
	mrpt::random::CRandomGenerator rng(7);
	const double sigma = 0.01, wallY = 1.0;
	auto scan = [&]() {
		return wallScan(std::atan2(wallY, 6.0), std::atan2(wallY, 0.5), mrpt::DEG2RAD(0.25), sigma, rng,
			[&](double) { return wallY; });
	};
	struct Spread
	{
		double sumErr2 = 0, sumPredicted = 0;
		size_t n = 0;
	};
	Spread weighted, tls;
	for (int trial = 0; trial < 400; trial++)
	{
		const ScanPoints s = scan();
		for (auto* out : {&weighted, &tls})
		{
			LineEllipseExtractor ex;
			ex.params.line_fit = out == &weighted ? "weighted" : "tls";
			// The far points' noise (1 cm x cos 80 deg) is below the default
			// 3 mm floor, which would make the prediction conservative.
			ex.params.min_point_sigma = 0.001;
			std::vector<ScanFeature> fs;
			ex.extract(s, fs);
			ASSERT_EQ(fs.size(), 1u);
			ASSERT_EQ(fs[0].kind, ScanFeature::Kind::Line);
			const double err = mrpt::math::wrapToPi(fs[0].alpha - M_PI / 2);
			out->sumErr2 += err * err;
			out->sumPredicted += fs[0].varAlpha;
			out->n++;
		}
	}
	const double varW = weighted.sumErr2 / weighted.n, varT = tls.sumErr2 / tls.n;
	std::printf("alpha sd: weighted %.4f deg (predicted %.4f), tls %.4f deg (predicted %.4f)\n",
		mrpt::RAD2DEG(std::sqrt(varW)), mrpt::RAD2DEG(std::sqrt(weighted.sumPredicted / weighted.n)),
		mrpt::RAD2DEG(std::sqrt(varT)), mrpt::RAD2DEG(std::sqrt(tls.sumPredicted / tls.n)));
	EXPECT_LT(varW, 0.8 * varT);
	for (const auto* f : {&weighted, &tls})
	{
		const double ratio = (f->sumErr2 / f->n) / (f->sumPredicted / f->n);
		EXPECT_GT(ratio, 0.75) << (f == &weighted ? "weighted" : "tls");
		EXPECT_LT(ratio, 1.33) << (f == &weighted ? "weighted" : "tls");
	}
}

// Along a wall seen at grazing incidence far away, 0.5 degree beams land
// farther apart than max_point_gap (0.9 m at 10 m here). Those far points
// give the wall's orientation its lever arm: with the adaptive breakpoint
// test (grazing_incidence, 5 deg) they stay in the wall's line, and its
// orientation is more precise than from the points the fixed gap alone
// keeps (0.0064 against 0.0105 deg sd here). A step to a wall 1 m behind still breaks.
TEST(LineEllipseExtractor, AWallSeenGrazinglyKeepsItsFarPoints)
{
	mrpt::random::CRandomGenerator rng(11);
	const double sigma = 0.01;
	// Beams from the bearing of (11, 1) to that of (0.5, 1) on the wall y = 1,
	// then (when `recess`) beams past x = 3 on a wall at y = 2 instead.
	auto scan = [&](bool recess) {
		return wallScan(std::atan2(1.0, 11.0), std::atan2(1.0, 0.5), mrpt::DEG2RAD(0.5), sigma, rng,
			[&](double b) { return recess && 1.0 / std::tan(b) > 3.0 ? 2.0 : 1.0; });
	};
	double sumErr2[2] = {0, 0};
	size_t farKept[2] = {0, 0};
	const int trials = 200;
	for (int trial = 0; trial < trials; trial++)
	{
		const ScanPoints s = scan(false);
		for (int grazing = 0; grazing < 2; grazing++)
		{
			LineEllipseExtractor ex;
			if (!grazing) ex.params.grazing_incidence = 0;
			std::vector<ScanFeature> fs;
			ex.extract(s, fs);
			// The longest line is the wall.
			const ScanFeature* wall = nullptr;
			for (const auto& f : fs)
				if (f.kind == ScanFeature::Kind::Line && (!wall || f.length > wall->length)) wall = &f;
			ASSERT_NE(wall, nullptr);
			const double err = mrpt::math::wrapToPi(wall->alpha - M_PI / 2);
			sumErr2[grazing] += err * err;
			// Points beyond 8.2 m, where consecutive points are > 0.6 m apart.
			for (uint32_t q = wall->firstPoint; q <= wall->lastPoint; q++)
				if (s.points[q].x > 8.2) farKept[grazing]++;
		}
	}
	const double sdFixed = std::sqrt(sumErr2[0] / trials), sdGrazing = std::sqrt(sumErr2[1] / trials);
	std::printf("wall orientation sd: fixed gap %.4f deg, with grazing_incidence %.4f deg; far points kept %zu / %zu\n",
		mrpt::RAD2DEG(sdFixed), mrpt::RAD2DEG(sdGrazing), farKept[0], farKept[1]);
	EXPECT_EQ(farKept[0], 0u);
	EXPECT_GE(farKept[1], 3u * trials);	 // x = 8.5, 9.2, 10.0 (11.0 may be trimmed)
	EXPECT_LT(sdGrazing, 0.75 * sdFixed);

	// A recess: no line holds points of both walls.
	LineEllipseExtractor ex;
	std::vector<ScanFeature> fs;
	const ScanPoints s = scan(true);
	ex.extract(s, fs);
	size_t lines = 0;
	for (const auto& f : fs)
	{
		if (f.kind != ScanFeature::Kind::Line) continue;
		lines++;
		bool near = false, far = false;
		for (uint32_t q = f.firstPoint; q <= f.lastPoint; q++)
			(s.points[q].y < 1.5 ? near : far) = true;
		EXPECT_FALSE(near && far) << "a line spans the step at x = 3 m";
	}
	EXPECT_EQ(lines, 2u);
}

// A rack's upright standing 5 cm out of the pallets' face, 10 cm wide, seen
// 1.3 m away at 1 cm noise with 0.25 deg beams (a Hokuyo UTM-30LX in an
// aisle of worlds/warehouse-aisles.ini): the split test cuts the face at
// it, and the RMS merge test alone (merge_step_points = 0) puts the face
// back together with the upright's points inside, a "line" whose offset
// and direction then depend on how many beams the upright takes from each
// viewpoint. With merge_step_points = 3 (the default), 3 consecutive
// points beyond the split threshold on one side keep the runs apart: no
// line holds the upright, and the face's lines are where the face is. (2
// split the plain wall of WeightedFitUsesTheGrazingPointsAndItsCovariance-
// Holds: its near points' noise is twice the cluster's estimate there.)
// Not on a range lattice, whose readings are off in runs of equal range.
TEST(LineEllipseExtractor, AnUprightStandingOutOfAWallIsNotMergedIntoIt)
{
	mrpt::random::CRandomGenerator rng(5);
	auto onUpright = [](const ScanPoint& p) { return p.x > 1.5 && p.x < 1.6; };
	size_t uprightInLine[3] = {0, 0, 0};
	double worstRho[2] = {0, 0};
	for (int trial = 0; trial < 20; trial++)
	{
		const ScanPoints s = wallScan(std::atan2(1.3, 6.0), std::atan2(1.3, -1.0), mrpt::DEG2RAD(0.25),
			0.01, rng, [](double b) {
				const double x = 1.3 / std::tan(b);
				return x > 1.5 && x < 1.6 ? 1.25 : 1.3;
			});
		// 2: the default on a range lattice (PcmFeatureMatcher sets the
		// lattice cell's sigma as rangeNoiseFloor), where runs of points on
		// one side are the lattice's: the RMS test alone.
		for (int steps = 0; steps < 3; steps++)
		{
			LineEllipseExtractor ex;
			// Step 8 (off by default) would fit the face's two pieces as one
			// line, whose span holds the upright: this test is about step 3.
			ex.params.collinear_fusion_chi2 = 0;
			if (!steps) ex.params.merge_step_points = 0;
			if (steps == 2) ex.rangeNoiseFloor = 0.16 / std::sqrt(12.0);
			std::vector<ScanFeature> fs;
			ex.extract(s, fs);
			for (const auto& f : fs)
			{
				if (f.kind != ScanFeature::Kind::Line) continue;
				size_t upright = 0;
				for (uint32_t q = f.firstPoint; q <= f.lastPoint; q++) upright += onUpright(s.points[q]);
				if (upright >= 2) uprightInLine[steps]++;
				if (steps < 2 && f.lastPoint - f.firstPoint > 50 && upright < 2)
					worstRho[steps] = std::max(worstRho[steps], std::abs(f.rho - 1.3));
			}
		}
	}
	EXPECT_EQ(uprightInLine[0], 20u) << "the RMS test alone no longer merges the upright: the test says nothing";
	EXPECT_EQ(uprightInLine[1], 0u);
	EXPECT_LT(worstRho[1], 0.003);
	EXPECT_EQ(uprightInLine[2], 20u) << "the step test ran on a range lattice";

	// One point beyond the threshold is a noise spike, not a step.
	mrpt::config::CConfigFileMemory c;
	c.setContent("[S]\nmerge_step_points = 1\n");
	const std::string message = test::errorMessageOf<ConfigError>(
		[&] { LineEllipseExtractor().params.loadFromConfigFile(c, "S"); });
	EXPECT_NE(message.find("merge_step_points"), std::string::npos) << message;
}

// A rack's face between its uprights (rackFaceScan: 10 cm wide, 5 cm out,
// every 2.7 m, their sides ray-cast; 300 viewpoints along the aisle). Step
// 3 keeps the face apart at every upright, and its pieces are off beyond
// their covariances: a few points of an upright's side, or of its front at
// a piece's grazing end, lie 1-5 cm out inside them, which the end trimming
// does not reach. Step 7 (line_outlier_sigmas) drops them; step 8
// (collinear_fusion_chi2) fits the pieces as one line, whose direction is
// then known to the square of the face's length over a piece's. A pallet
// pushed 15 cm out of its bay is not the face and stays apart from it; a
// plain wall is left as it was.
TEST(LineEllipseExtractor, ARacksFaceBetweenItsUprightsIsOneLineWhereTheFaceIs)
{
	struct Stats
	{
		double nees = 0, alpha2 = 0;
		std::vector<double> absAlpha;  //!< |alpha error| of each face line [rad]
		size_t lines = 0, palletInFace = 0;
	};
	auto run = [](double depth, bool pallet, double outlierSigmas, double fusionChi2) {
		mrpt::random::CRandomGenerator rng(7);
		Stats st;
		std::vector<int> hit;
		for (int trial = 0; trial < 300; trial++)
		{
			const ScanPoints s = rackFaceScan(-2.0 + 0.01 * trial, depth, pallet, rng, hit);
			LineEllipseExtractor ex;
			ex.params.line_outlier_sigmas = outlierSigmas;
			ex.params.collinear_fusion_chi2 = fusionChi2;
			std::vector<ScanFeature> fs;
			ex.extract(s, fs);
			for (const auto& f : fs)
			{
				if (f.kind != ScanFeature::Kind::Line || std::abs(f.rho - 1.3) > 0.02) continue;
				const double er = f.rho - 1.3, ea = mrpt::math::wrapToPi(f.alpha - M_PI / 2);
				const double det = f.varRho * f.varAlpha - f.covRhoAlpha * f.covRhoAlpha;
				st.nees += (f.varAlpha * er * er - 2 * f.covRhoAlpha * er * ea + f.varRho * ea * ea) / det;
				st.alpha2 += ea * ea;
				st.absAlpha.push_back(std::abs(ea));
				st.lines++;
				// A line holding the pallet's front: 30 or more of its beams
				// (the pallet takes 80-600) in its span.
				size_t onPallet = 0;
				for (uint32_t q = f.firstPoint; q <= f.lastPoint; q++)
					onPallet += hit[q] && s.points[q].y < 1.2;
				st.palletInFace += onPallet >= 30;
			}
		}
		return st;
	};
	auto rmsAlphaDeg = [](const Stats& st) { return mrpt::RAD2DEG(std::sqrt(st.alpha2 / st.lines)); };
	auto medianAlphaDeg = [](Stats st) {
		std::nth_element(st.absAlpha.begin(), st.absAlpha.begin() + st.absAlpha.size() / 2, st.absAlpha.end());
		return mrpt::RAD2DEG(st.absAlpha[st.absAlpha.size() / 2]);
	};
	const Stats neither = run(0.05, false, 0, 0), outliers = run(0.05, false, 3, 0),
				both = run(0.05, false, 3, 9.21);
	// The pieces alone: off beyond their covariances.
	EXPECT_GT(neither.nees / neither.lines, 3.0);
	EXPECT_GT(neither.lines, 900u);
	// Step 7: consistent pieces.
	EXPECT_LT(outliers.nees / outliers.lines, 2.5);
	// Steps 7 and 8: about one line per scan, consistent, its direction
	// five times better than the pieces' (measured: 0.0044 against 0.036 deg).
	EXPECT_LT(both.lines, 400u);
	EXPECT_LT(both.nees / both.lines, 2.5);
	// (In the median: a few short lines of an upright's front and the face
	// next to it, 2-5 deg off, are in every variant and make the RMS.)
	EXPECT_LT(medianAlphaDeg(both), 0.2 * medianAlphaDeg(neither));
	// Both are off by default (the real calibration log, doc/benchmarks.md).
	const LineEllipseExtractor::Parameters defaults;
	EXPECT_EQ(defaults.line_outlier_sigmas, 0.0);
	EXPECT_EQ(defaults.collinear_fusion_chi2, 0.0);

	// The pushed-out pallet is its own line, never the face's.
	const Stats withPallet = run(0.05, true, 3, 9.21);
	EXPECT_EQ(withPallet.palletInFace, 0u);
	EXPECT_GT(withPallet.lines, 250u);

	// A plain wall: nothing to drop, nothing to fuse.
	const Stats plainOff = run(0, false, 0, 0), plainOn = run(0, false, 3, 9.21);
	EXPECT_EQ(plainOn.lines, plainOff.lines);
	EXPECT_LT(rmsAlphaDeg(plainOn), 1.1 * rmsAlphaDeg(plainOff));
	EXPECT_LT(medianAlphaDeg(plainOn), 1.1 * medianAlphaDeg(plainOff));

	for (const char* key : {"line_outlier_sigmas", "collinear_fusion_chi2"})
	{
		mrpt::config::CConfigFileMemory c;
		c.setContent(std::string("[S]\n") + key + " = -1\n");
		const std::string message = test::errorMessageOf<ConfigError>(
			[&] { LineEllipseExtractor().params.loadFromConfigFile(c, "S"); });
		EXPECT_NE(message.find(key), std::string::npos) << message;
	}
}
