// The Cramer-Rao bound of scan matching (issue "scan matchers that hold
// up", item 6): each scan's Fisher information against the true surfaces,
// and the bound of a pair's relative pose.
#include <gtest/gtest.h>
#include <mrpt/math/wrap2pi.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/random/RandomGenerators.h>

#include <Eigen/Dense>
#include <cmath>

#include "featloc/eval/ScanPairCramerRaoBound.h"
#include "featloc/sim/RangeScanFisherInformation.h"
#include "featloc/sim/RayCaster.h"

using namespace featloc;
using mrpt::poses::CPose2D;

namespace
{
/** An 8 x 6 m room with a slanted wall piece and a pillar. */
SimWorld room()
{
	SimWorld w;
	auto wall = [&](double x0, double y0, double x1, double y1) {
		WallSegment s;
		s.a = {x0, y0};
		s.b = {x1, y1};
		w.addSegment(s);
	};
	wall(0, 0, 8, 0);
	wall(8, 0, 8, 6);
	wall(8, 6, 0, 6);
	wall(0, 6, 0, 0);
	wall(5, 4.5, 6.5, 5.5);
	CircleShape pillar;
	pillar.centre = {6, 2};
	pillar.radius = 0.3;
	w.addCircle(pillar);
	return w;
}

const CPose2D kMount(0.2, 0.1, 0.17);  // a lever arm, so yaw moves the sensor

/** The exact ranges of a 181-beam, 180-degree scan from `robot`. */
std::vector<double> exactRanges(const SimWorld& w, const CPose2D& robot, double t = 0)
{
	std::vector<CircleShape> circles;
	w.circlesAt(t, circles);
	std::vector<double> r;
	RayCaster::cast((robot + kMount).asTPose(), -M_PI / 2, M_PI / 180, 181, 30, w.segments(),
		circles, r);
	return r;
}

/** d ranges / d (x, y, yaw) of the robot by central differences. */
Eigen::MatrixXd rangeJacobian(const SimWorld& w, const Eigen::Vector3d& x)
{
	const size_t n = exactRanges(w, CPose2D(x[0], x[1], x[2])).size();
	Eigen::MatrixXd J(n, 3);
	for (int p = 0; p < 3; p++)
	{
		const double h = 1e-6;
		Eigen::Vector3d xp = x, xm = x;
		xp[p] += h;
		xm[p] -= h;
		const auto rp = exactRanges(w, CPose2D(xp[0], xp[1], xp[2]));
		const auto rm = exactRanges(w, CPose2D(xm[0], xm[1], xm[2]));
		for (size_t i = 0; i < n; i++) J(i, p) = (rp[i] - rm[i]) / (2 * h);
	}
	return J;
}

mrpt::obs::CObservation2DRangeScan scanOf(const std::vector<double>& ranges, double sigma)
{
	mrpt::obs::CObservation2DRangeScan s;
	s.aperture = static_cast<float>(M_PI);
	s.rightToLeft = true;
	s.maxRange = 30;
	s.stdError = static_cast<float>(sigma);
	s.sensorPose = mrpt::poses::CPose3D(kMount);
	s.resizeScan(ranges.size());
	for (size_t i = 0; i < ranges.size(); i++)
	{
		s.setScanRange(i, static_cast<float>(std::isfinite(ranges[i]) ? ranges[i] : 30));
		s.setScanRangeValidity(i, std::isfinite(ranges[i]));
	}
	return s;
}
}  // namespace

// The bound is reached by the maximum-likelihood estimator that knows the
// room (Gauss-Newton on the ranges, its Jacobian by finite differences of
// the ray caster: independent of the bound's analytic derivatives, lever
// arm included): over 400 noisy scans its errors have the bound's
// covariance (NEES 3, each variance within 20%).
TEST(RangeScanFisherInformation, MaximumLikelihoodLocalizationReachesTheBound)
{
	const SimWorld w = room();
	const CPose2D truth(3.1, 2.4, 0.3);
	const double sigma = 0.02;
	const std::vector<double> exact = exactRanges(w, truth);
	const auto fisher = RangeScanFisherInformation::of(w, 0, scanOf(exact, sigma), truth);
	EXPECT_EQ(fisher.beamsUsed, 181u);
	EXPECT_EQ(fisher.beamsOff, 0u);
	const Eigen::Matrix3d info = fisher.information.asEigen();
	const Eigen::Matrix3d bound = info.inverse();
	// The analytic information is J^T J / sigma^2 of the numerical Jacobian.
	const Eigen::MatrixXd J = rangeJacobian(w, Eigen::Vector3d(truth.x(), truth.y(), truth.phi()));
	const Eigen::Matrix3d numeric = J.transpose() * J / (sigma * sigma);
	EXPECT_LT((info - numeric).norm(), 1e-6 * info.norm()) << info << "\n" << numeric;

	mrpt::random::CRandomGenerator rng(7);
	const int draws = 400;
	Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
	double nees = 0;
	for (int d = 0; d < draws; d++)
	{
		std::vector<double> z = exact;
		for (auto& r : z) r += sigma * rng.drawGaussian1D_normalized();
		Eigen::Vector3d x(truth.x(), truth.y(), truth.phi());
		for (int it = 0; it < 4; it++)
		{
			const std::vector<double> r0 = exactRanges(w, CPose2D(x[0], x[1], x[2]));
			const Eigen::MatrixXd J = rangeJacobian(w, x);
			Eigen::VectorXd nu(z.size());
			for (size_t i = 0; i < z.size(); i++) nu[i] = z[i] - r0[i];
			x += (J.transpose() * J).ldlt().solve(J.transpose() * nu);
		}
		Eigen::Vector3d e = x - Eigen::Vector3d(truth.x(), truth.y(), truth.phi());
		e[2] = mrpt::math::wrapToPi(e[2]);
		scatter += e * e.transpose() / draws;
		nees += e.dot(info * e) / draws;
	}
	// 400 draws: the mean NEES has sd sqrt(6 / 400) = 0.12.
	EXPECT_NEAR(nees, 3.0, 0.4);
	for (int p = 0; p < 3; p++)
		EXPECT_NEAR(scatter(p, p) / bound(p, p), 1.0, 0.2) << "axis " << p;
}

// Beams on a walking person carry nothing about the pose (the person moves
// between scans): the information is that of the scan without them. A scan
// taken elsewhere is told apart by its ranges.
TEST(RangeScanFisherInformation, PeopleAndInvalidBeamsCountForNothing)
{
	SimWorld w = room();
	WalkingAgent::Params person;
	person.shape = WalkingAgent::Shape::Body;
	person.waypoints = {{4.5, 2.4}, {4.5, 2.5}};
	person.mode = WalkingAgent::Mode::Once;
	person.startTime = 100;	 // stands at its first waypoint
	w.addAgent(person);
	const CPose2D truth(3.1, 2.4, 0.0);
	const std::vector<double> seen = exactRanges(w, truth);
	const std::vector<double> walls = exactRanges(room(), truth);
	auto blinded = seen;
	size_t onPerson = 0;
	for (size_t i = 0; i < seen.size(); i++)
		if (seen[i] < walls[i] - 1e-9)
		{
			blinded[i] = std::numeric_limits<double>::infinity();
			onPerson++;
		}
	ASSERT_GT(onPerson, 5u);
	const auto withPerson = RangeScanFisherInformation::of(w, 0, scanOf(seen, 0.01), truth);
	const auto without = RangeScanFisherInformation::of(room(), 0, scanOf(blinded, 0.01), truth);
	EXPECT_EQ(withPerson.beamsUsed, 181 - onPerson);
	EXPECT_EQ(without.beamsUsed, 181 - onPerson);
	EXPECT_LT((withPerson.information.asEigen() - without.information.asEigen()).norm(),
		1e-9 * without.information.asEigen().norm());
	EXPECT_EQ(withPerson.beamsOff, 0u);

	const auto elsewhere =
		RangeScanFisherInformation::of(room(), 0, scanOf(walls, 0.01), CPose2D(3.3, 2.4, 0));
	EXPECT_GT(elsewhere.beamsOff, 181u / 10);  // featloc-bench refuses a world where over 10% are off
	mrpt::obs::CObservation2DRangeScan silent = scanOf(walls, 0.01);
	silent.stdError = 0;
	EXPECT_THROW(RangeScanFisherInformation::of(room(), 0, silent, truth), std::invalid_argument);
}

// A pair's bound: the two poses' bounds carried into the relative pose
// (their sum when both are at the origin), and the mean errors of the
// Gaussian it bounds, against a Monte-Carlo draw of it.
TEST(ScanPairCramerRaoBound, RelativePoseBoundAndItsMeanErrors)
{
	Eigen::Matrix3d a;
	a << 4e-6, 1e-6, 2e-7, 1e-6, 1e-6, 1e-7, 2e-7, 1e-7, 1e-6;
	Eigen::Matrix3d b;
	b << 1e-6, -2e-7, 0, -2e-7, 9e-6, 3e-7, 0, 3e-7, 4e-6;
	const auto atOrigin = ScanPairCramerRaoBound::of(CPose2D(), mrpt::math::CMatrixDouble33(a.inverse()),
		CPose2D(), mrpt::math::CMatrixDouble33(b.inverse()));
	ASSERT_TRUE(atOrigin.bounded);
	EXPECT_LT((atOrigin.cov.asEigen() - (a + b)).norm(), 1e-12);

	const auto bound = ScanPairCramerRaoBound::of(CPose2D(1, 2, 0.5),
		mrpt::math::CMatrixDouble33(a.inverse()), CPose2D(1.8, 2.3, 0.9),
		mrpt::math::CMatrixDouble33(b.inverse()));
	ASSERT_TRUE(bound.bounded);
	const Eigen::LLT<Eigen::Matrix3d> llt(bound.cov.asEigen());
	mrpt::random::CRandomGenerator rng(3);
	double t = 0, w = 0;
	const int draws = 200000;
	for (int d = 0; d < draws; d++)
	{
		Eigen::Vector3d z(rng.drawGaussian1D_normalized(), rng.drawGaussian1D_normalized(),
			rng.drawGaussian1D_normalized());
		const Eigen::Vector3d e = llt.matrixL() * z;
		t += std::hypot(e[0], e[1]) / draws;
		w += std::abs(e[2]) / draws;
	}
	EXPECT_NEAR(bound.meanTrans / t, 1.0, 0.01);
	EXPECT_NEAR(bound.meanYaw / w, 1.0, 0.01);

	// A scan that sees one wall only cannot fix the motion along it.
	mrpt::math::CMatrixDouble33 corridor;
	corridor.setZero();
	corridor(1, 1) = 1e4;
	corridor(2, 2) = 1e3;
	EXPECT_FALSE(ScanPairCramerRaoBound::of(CPose2D(), corridor, CPose2D(),
		mrpt::math::CMatrixDouble33(b.inverse())).bounded);
}
