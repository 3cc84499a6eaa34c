// Borges & Aldon's PCM matcher: the closed-form motion step and the
// matcher on synthetic scans with known motion.
#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/math/wrap2pi.h>
#include <mrpt/random/RandomGenerators.h>

#include <Eigen/Dense>
#include <cmath>

#include "featloc/math/DiagonalPoseGaussian.h"
#include "featloc/matchers/PcmFeatureMatcher.h"
#include "featloc/matchers/PcmMotionUpdate.h"
#include "featloc/matchers/ScanMatcherFactory.h"
#include "featloc/registerClasses.h"
#include "support/MatcherTestHelpers.h"
#include "support/SyntheticRoom.h"

using namespace featloc;
using featloc::test::SyntheticRoom;
using mrpt::math::TPose2D;
using mrpt::poses::CPose2D;

namespace
{
/** PCM without its fallback matcher: these tests are about PCM's own
 * answers and failures. */
ScanMatcher::Ptr pcmAlone()
{
	return featloc::test::configuredMatcher("featloc::PcmFeatureMatcher", "fallback_class=");
}

ScanFeature line(double rho, double alpha)
{
	ScanFeature f;
	f.kind = ScanFeature::Kind::Line;
	f.rho = rho;
	f.alpha = alpha;
	f.x = rho * std::cos(alpha);
	f.y = rho * std::sin(alpha);
	f.a2 = std::cos(alpha) * std::cos(alpha);
	f.b2 = std::sin(alpha) * std::sin(alpha);
	f.c = std::cos(alpha) * std::sin(alpha);
	return f;
}

ScanFeature blob(double x, double y)
{
	ScanFeature f;
	f.kind = ScanFeature::Kind::Ellipse;
	f.x = x;
	f.y = y;
	return f;
}

/** Numerical minimum of E: many Gauss-Newton starts on (t, w), the best. */
TPose2D numericalMinimum(
	const std::vector<ScanFeature>& ref, const std::vector<ScanFeature>& cur,
	const std::vector<FeaturePair>& pairs)
{
	auto E = [&](const Eigen::Vector3d& x) {
		return PcmMotionUpdate::cost(ref, cur, pairs, TPose2D(x[0], x[1], x[2]));
	};
	Eigen::Vector3d best(0, 0, 0);
	double bestE = 1e300;
	for (int start = 0; start < 36; start++)
	{
		Eigen::Vector3d x(0, 0, -M_PI + start * M_PI / 18);
		for (int it = 0; it < 200; it++)
		{
			// Newton with finite differences (gradient and Hessian).
			const double h = 1e-5;
			Eigen::Vector3d g;
			Eigen::Matrix3d H;
			for (int a = 0; a < 3; a++)
			{
				Eigen::Vector3d ea = Eigen::Vector3d::Zero();
				ea[a] = h;
				g[a] = (E(x + ea) - E(x - ea)) / (2 * h);
				for (int b = 0; b < 3; b++)
				{
					Eigen::Vector3d eb = Eigen::Vector3d::Zero();
					eb[b] = h;
					H(a, b) = (E(x + ea + eb) - E(x + ea - eb) - E(x - ea + eb) + E(x - ea - eb)) /
						(4 * h * h);
				}
			}
			Eigen::Vector3d step = -(H + 1e-9 * Eigen::Matrix3d::Identity()).ldlt().solve(g);
			if (!std::isfinite(step.norm())) break;
			double lambda = 1;
			while (lambda > 1e-6 && E(x + lambda * step) > E(x)) lambda /= 2;
			x += lambda * step;
			if (step.norm() * lambda < 1e-12) break;
		}
		if (E(x) < bestE)
		{
			bestE = E(x);
			best = x;
		}
	}
	return TPose2D(best[0], best[1], mrpt::math::wrapToPi(best[2]));
}

/** A room made only of long walls and boxes (every side > 0.6 m): all
 * features are lines, exact on noise-free scans. */
SyntheticRoom linesRoom()
{
	SyntheticRoom r;
	r.add(-5, -3, 5, -3);
	r.add(5, -3, 5, 1);
	r.add(5, 1, 6, 1);
	r.add(6, 1, 6, 3);
	r.add(6, 3, -5, 3);
	r.add(-5, 3, -5, -3);
	r.add(1.5, -1.8, 2.5, -1.2);  // a slanted crate
	r.add(2.5, -1.2, 1.9, -0.2);
	r.add(-2.5, 0.8, -1.5, 0.8);  // a table
	r.add(-1.5, 0.8, -1.5, 1.6);
	return r;
}
}  // namespace

TEST(PcmMotionUpdate, ClosedFormEqualsNumericalMinimumOfTheCost)
{
	mrpt::random::CRandomGenerator rng(9);
	for (int trial = 0; trial < 15; trial++)
	{
		std::vector<ScanFeature> ref, cur;
		std::vector<FeaturePair> pairs;
		for (int i = 0; i < 6; i++)
		{
			ref.push_back(i % 3 ? line(rng.drawUniform(1.0, 6.0), rng.drawUniform(-M_PI, M_PI))
								: blob(rng.drawUniform(-5.0, 5.0), rng.drawUniform(-5.0, 5.0)));
			ScanFeature moved = ref.back();
			moved.x += 0.2 * rng.drawGaussian1D_normalized();
			moved.y += 0.2 * rng.drawGaussian1D_normalized();
			cur.push_back(moved);
		}
		for (uint32_t i = 0; i < 6; i++)
			for (uint32_t j = 0; j < 6; j++)
				if (ref[i].kind == cur[j].kind)
					pairs.push_back({i, j, i == j ? rng.drawUniform(0.5, 1.0) : rng.drawUniform(0.0, 0.1)});
		const TPose2D start(0.1, -0.2, 0.3);
		const TPose2D closed = PcmMotionUpdate::solve(ref, cur, pairs, start, 0);
		const TPose2D numeric = numericalMinimum(ref, cur, pairs);
		const double eClosed = PcmMotionUpdate::cost(ref, cur, pairs, closed);
		const double eNumeric = PcmMotionUpdate::cost(ref, cur, pairs, numeric);
		EXPECT_LE(eClosed, eNumeric * (1 + 1e-9) + 1e-12) << "trial " << trial;
		EXPECT_NEAR(closed.x, numeric.x, 1e-5) << "trial " << trial;
		EXPECT_NEAR(closed.y, numeric.y, 1e-5) << "trial " << trial;
		EXPECT_NEAR(mrpt::math::wrapToPi(closed.phi - numeric.phi), 0, 1e-5) << "trial " << trial;
	}
}

TEST(PcmMotionUpdate, PrintedEquation23WithoutQWouldBeWrong)
{
	// Exact correspondences under a known motion: the corrected equation
	// recovers it; dropping q (as printed) does not satisfy dE/dw = 0.
	const TPose2D truth(0.4, -0.25, 0.2);
	std::vector<ScanFeature> ref = {line(3, 0.1), line(2.5, 1.7), line(4, -1.4), blob(1, 2), blob(-2, 1)};
	std::vector<ScanFeature> cur;
	for (const auto& f : ref)
	{
		ScanFeature g = f;
		PcmMotionUpdate::predict(f, truth, g.x, g.y);
		cur.push_back(g);
	}
	std::vector<FeaturePair> pairs;
	for (uint32_t i = 0; i < ref.size(); i++) pairs.push_back({i, i, 1.0});
	const TPose2D m = PcmMotionUpdate::solve(ref, cur, pairs, TPose2D(0, 0, 0), 0);
	EXPECT_NEAR(m.x, truth.x, 1e-12);
	EXPECT_NEAR(m.y, truth.y, 1e-12);
	EXPECT_NEAR(m.phi, truth.phi, 1e-12);
	EXPECT_NEAR(PcmMotionUpdate::cost(ref, cur, pairs, m), 0, 1e-20);

	// The printed form, beta^T P M^-1 N beta + beta^T (r + P M^-1) = 0, read
	// as beta^T (P M^-1 N) beta + beta^T r = 0: its residual at the truth.
	Eigen::Matrix2d M = Eigen::Matrix2d::Zero(), N = Eigen::Matrix2d::Zero();
	Eigen::Vector2d q = Eigen::Vector2d::Zero(), r = Eigen::Vector2d::Zero();
	for (const auto& p : pairs)
	{
		Eigen::Matrix2d A, F;
		A << ref[p.i].a2, ref[p.i].c, ref[p.i].c, ref[p.i].b2;
		F << cur[p.j].x, -cur[p.j].y, cur[p.j].y, cur[p.j].x;
		M += A;
		N -= A * F;
		q += A * Eigen::Vector2d(ref[p.i].x, ref[p.i].y);
		r += Eigen::Vector2d(ref[p.i].y * cur[p.j].x - ref[p.i].x * cur[p.j].y,
			-ref[p.i].x * cur[p.j].x - ref[p.i].y * cur[p.j].y);
	}
	Eigen::Matrix2d P;
	P << 0, 1, -1, 0;
	P = P * N.transpose();
	const Eigen::Vector2d beta(std::cos(truth.phi), std::sin(truth.phi));
	const double corrected =
		beta.dot(P * M.inverse() * N * beta) + beta.dot(r + P * M.inverse() * q);
	const double printed = beta.dot(P * M.inverse() * N * beta) + beta.dot(r);
	EXPECT_NEAR(corrected, 0, 1e-10);
	EXPECT_GT(std::abs(printed), 0.1);
}

TEST(PcmFeatureMatcher, NoiseFreePairRecoveredFromLargeInitialErrors)
{
	registerClasses();
	const SyntheticRoom room = linesRoom();
	auto m = pcmAlone();
	auto& pcm = dynamic_cast<PcmFeatureMatcher&>(*m);
	pcm.params.initial_bounds_source = "config";  // the paper's protocol bounds
	mrpt::random::CRandomGenerator rng(5);
	for (int trial = 0; trial < 20; trial++)
	{
		const CPose2D p0(rng.drawUniform(-2.0, 1.0), rng.drawUniform(-1.0, 1.0),
			rng.drawUniform(-0.5, 0.5));
		const CPose2D motion(rng.drawUniform(-0.5, 0.5), rng.drawUniform(-0.5, 0.5),
			mrpt::DEG2RAD(rng.drawUniform(-15.0, 15.0)));
		const auto ref = room.scan(p0, CPose2D(0.2, 0, 0), 361, M_PI * 1.5);
		const auto cur = room.scan(p0 + motion, CPose2D(0.2, 0, 0), 361, M_PI * 1.5);
		// Initial error: 0.3 m on each axis, 10 degrees (signs vary).
		const double sx = trial % 2 ? 1 : -1, sy = trial % 4 < 2 ? 1 : -1;
		const CPose2D start(motion.x() + 0.3 * sx, motion.y() + 0.3 * sy,
			motion.phi() + sx * sy * mrpt::DEG2RAD(10.0));
		const MatchResult r = m->match(*ref, *cur, diagonalPoseGaussian(start, 0.17, 0.1));
		ASSERT_TRUE(r.success) << "trial " << trial << ": " << r.failureReason;
		EXPECT_LT(std::abs(r.estimate.mean.x() - motion.x()), 0.001) << "trial " << trial;
		EXPECT_LT(std::abs(r.estimate.mean.y() - motion.y()), 0.001) << "trial " << trial;
		EXPECT_LT(std::abs(mrpt::math::wrapToPi(r.estimate.mean.phi() - motion.phi())),
			mrpt::DEG2RAD(0.01))
			<< "trial " << trial;
		EXPECT_LE(r.iterations, pcm.params.max_iterations);
		EXPECT_GT(r.goodness, 0.5);
	}
}

TEST(PcmFeatureMatcher, CovarianceIsConsistentOverNoisyTrials)
{
	registerClasses();
	const SyntheticRoom room = linesRoom();
	auto m = pcmAlone();
	mrpt::random::CRandomGenerator rng(11);
	const double noise = 0.01;
	auto noisy = [&](mrpt::obs::CObservation2DRangeScan::Ptr s) {
		for (size_t i = 0; i < s->getScanSize(); i++)
			if (s->getScanRangeValidity(i))
				s->setScanRange(i, s->getScanRange(i) +
					static_cast<float>(noise * rng.drawGaussian1D_normalized()));
		return s;
	};
	const int trials = 300;
	double neesSum = 0;
	int used = 0;
	for (int trial = 0; trial < trials; trial++)
	{
		// In the free middle of the room, at least 0.5 m from the obstacles.
		const CPose2D p0(rng.drawUniform(-1.0, 1.0), rng.drawUniform(-1.0, 0.3),
			rng.drawUniform(-0.5, 0.5));
		const CPose2D motion(rng.drawUniform(-0.3, 0.3), rng.drawUniform(-0.3, 0.3),
			mrpt::DEG2RAD(rng.drawUniform(-10.0, 10.0)));
		const auto ref = noisy(room.scan(p0, CPose2D(), 361, M_PI * 1.5));
		const auto cur = noisy(room.scan(p0 + motion, CPose2D(), 361, M_PI * 1.5));
		const MatchResult r = m->match(*ref, *cur, diagonalPoseGaussian(motion, 0.05, 0.03));
		ASSERT_TRUE(r.success) << r.failureReason;
		Eigen::Vector3d e(r.estimate.mean.x() - motion.x(), r.estimate.mean.y() - motion.y(),
			mrpt::math::wrapToPi(r.estimate.mean.phi() - motion.phi()));
		neesSum += e.dot(r.estimate.cov.asEigen().inverse() * e);
		used++;
	}
	// Average NEES of 3-dof estimates: within the chi-square 95% band.
	const double mean = neesSum / used;
	const double half = 1.96 * std::sqrt(6.0 / used);
	EXPECT_GT(mean, 3 - half) << mean;
	EXPECT_LT(mean, 3 + half) << mean;
}

TEST(PcmFeatureMatcher, CorridorIsFlaggedWithItsUnconstrainedDirection)
{
	registerClasses();
	const SyntheticRoom corridor = SyntheticRoom::corridor();  // walls y = +-1
	auto m = pcmAlone();
	const auto ref = corridor.scan(CPose2D(0, 0, 0));
	const auto cur = corridor.scan(CPose2D(0.3, 0.05, 0.02));
	const MatchResult r = m->match(*ref, *cur, diagonalPoseGaussian(CPose2D(0.25, 0, 0), 0.1, 0.05));
	EXPECT_FALSE(r.success);
	EXPECT_NE(r.failureReason.find("translation along direction (1.00, 0.00)"),
		std::string::npos)
		<< r.failureReason;
	// What the features do constrain is still estimated.
	EXPECT_NEAR(r.estimate.mean.y(), 0.05, 0.005);
	EXPECT_NEAR(r.estimate.mean.phi(), 0.02, 0.002);
}

TEST(PcmFeatureMatcher, TooFewFeaturesIsAReportedFailure)
{
	registerClasses();
	SyntheticRoom pole;
	pole.add(1, -0.05, 1, 0.05);  // a 10 cm stub: no feature
	auto m = pcmAlone();
	const auto s = pole.scan(CPose2D());
	const MatchResult r = m->match(*s, *s, diagonalPoseGaussian(CPose2D(), 0.1, 0.1));
	EXPECT_FALSE(r.success);
	EXPECT_NE(r.failureReason.find("no features"), std::string::npos) << r.failureReason;
}

// The switches that make PcmFeatureMatcher the paper's (doc/pcm-matcher.md):
// featloc's motion window fails an estimate far outside the guess's
// bounds, the paper's method returns it; the paper's one-corner d_max gives
// narrower memberships than the largest over the eight corners, so the
// iterations take longer; a bad value names its key.
TEST(PcmFeatureMatcher, AsPublishedSwitchesTurnOffTheWindowAndTheEightCorners)
{
	registerClasses();
	const SyntheticRoom room = linesRoom();
	const CPose2D motion(0.35, -0.1, mrpt::DEG2RAD(4));
	const auto ref = room.scan(CPose2D(-1, 0, 0.2), CPose2D(0.2, 0, 0), 361, M_PI * 1.5);
	const auto cur = room.scan(CPose2D(-1, 0, 0.2) + motion, CPose2D(0.2, 0, 0), 361, M_PI * 1.5);
	// The guess says "no motion", sure to 5 cm: Delta_0 = 0.15 m, and the
	// truth is 0.35 m away in x, beyond 2 Delta_0. PCM finds it.
	const auto guess = diagonalPoseGaussian(CPose2D(), 0.05, mrpt::DEG2RAD(2));
	auto run = [&](double window) {
		auto m = pcmAlone();
		dynamic_cast<PcmFeatureMatcher&>(*m).params.motion_window_bounds = window;
		return m->match(*ref, *cur, guess);
	};
	const MatchResult featloc = run(2);
	EXPECT_FALSE(featloc.success);
	EXPECT_NE(featloc.failureReason.find("left the motion bounds"), std::string::npos)
		<< featloc.failureReason;
	const MatchResult paper = run(0);
	EXPECT_TRUE(paper.success) << paper.failureReason;
	EXPECT_NEAR(paper.estimate.mean.x(), motion.x(), 1e-3);
	EXPECT_NEAR(paper.estimate.mean.y(), motion.y(), 1e-3);

	// Guess sure to 2 cm / 1 deg: the paper's corner (+, +, +) gives the
	// memberships less room than the worst of the eight, and the
	// iterations take longer to the same answer.
	const auto sure = diagonalPoseGaussian(CPose2D(), 0.02, mrpt::DEG2RAD(1));
	auto iterations = [&](const std::string& dmax) {
		auto m = pcmAlone();
		auto& pcm = dynamic_cast<PcmFeatureMatcher&>(*m);
		pcm.params.dmax_corners = dmax;
		pcm.params.motion_window_bounds = 0;
		m->coarseSearchOptions().enabled = false;  // the paper's iterations from the guess
		const MatchResult r = m->match(*ref, *cur, sure);
		EXPECT_TRUE(r.success) << dmax << ": " << r.failureReason;
		EXPECT_NEAR(r.estimate.mean.x(), motion.x(), 1e-3) << dmax;
		return r.iterations;
	};
	EXPECT_GT(iterations("published"), iterations("all"));

	mrpt::config::CConfigFileMemory bad;
	bad.write("ScanMatcher.PcmFeatureMatcher", "dmax_corners", "one");
	PcmFeatureMatcher::Parameters p;
	try
	{
		p.loadFromConfigFile(bad, "ScanMatcher.PcmFeatureMatcher");
		ADD_FAILURE() << "dmax_corners = one was accepted";
	}
	catch (const std::exception& e)
	{
		EXPECT_NE(std::string(e.what()).find("dmax_corners"), std::string::npos) << e.what();
	}
}
