// The vertical-line landmarks of Moon, Miura & Shirai, section 5, in
// EkfLocalizer: the constraint of eq. (20) against finite differences, its
// update against a dense EKF built from numeric Jacobians, on-line start
// from eq. (15)/(17), association by wall and polarity, the subset of least
// uncertain landmarks, removal beside point landmarks, and consistency
// (NEES) over Monte-Carlo runs.
#include <gtest/gtest.h>
#include <mrpt/math/distributions.h>
#include <mrpt/math/wrap2pi.h>
#include <mrpt/poses/CPosePDFGaussian.h>
#include <mrpt/random/RandomGenerators.h>

#include <Eigen/Dense>
#include <cmath>
#include <functional>

#include "featloc/ekf/EkfLocalizer.h"
#include "featloc/ekf/VerticalLandmarkConstraint.h"
#include "featloc/math/DiagonalPoseGaussian.h"

using namespace featloc;
using mrpt::poses::CPose2D;
using mrpt::poses::CPosePDFGaussian;

namespace
{
/** Variance vxy in x and y, vyaw in yaw. */
CPosePDFGaussian gaussian(const CPose2D& mean, double vxy, double vyaw)
{
	return diagonalPoseGaussian(mean, std::sqrt(vxy), std::sqrt(vyaw));
}

/** The observation of landmark l (x, y, low, high) from robot X, exact,
 * with the given sigmas (position isotropic), on wall `wall`. */
VerticalLandmarkObservation seen(
	const Eigen::Vector3d& X, const Eigen::Vector4d& l, double sigma, double sigmaEnd, size_t wall = 0,
	int polarity = 1)
{
	VerticalLandmarkObservation z;
	const double c = std::cos(X.z()), s = std::sin(X.z());
	const Eigen::Vector2d d = l.head<2>() - X.head<2>();
	z.position = {c * d.x() + s * d.y(), -s * d.x() + c * d.y()};
	z.covariance = Eigen::Matrix2d::Identity() * sigma * sigma;
	z.lLow = l[2];
	z.lHigh = l[3];
	z.sigmaLow = z.sigmaHigh = sigmaEnd;
	z.wall = wall;
	z.polarity = polarity;
	return z;
}

/** A selected feature on the wall y = 4 (direction x): it may start a
 * landmark with the rank-1 covariance of eq. (17). */
VerticalLandmarkObservation startable(
	const Eigen::Vector3d& X, const Eigen::Vector4d& l, double sigmaAlong, size_t wall = 0, int polarity = 1)
{
	auto z = seen(X, l, 0.02, 0.01, wall, polarity);
	z.canStart = true;
	z.start = l.head<2>();
	z.startCovariance = Eigen::Vector2d(1, 0) * Eigen::Vector2d(1, 0).transpose() * sigmaAlong * sigmaAlong;
	return z;
}

/** featloc's wall observation of the wall y = 4 (x from -3 to 3) from
 * robot X, exact, in the plane frame the Monte-Carlo's plane errors use:
 * origin at the robot, s along robot y, w along robot x (J = [1 s] moves a
 * point's robot x). */
StereoWallObservation wallSeen(const Eigen::Vector3d& X, const Eigen::Matrix2d& cov, size_t wall = 0)
{
	StereoWallObservation w;
	w.wall = wall;
	w.mapA = {-3, 4};
	w.mapB = {3, 4};
	w.origin = Eigen::Vector2d::Zero();
	w.e = Eigen::Vector2d::UnitY();
	w.n = Eigen::Vector2d::UnitX();
	w.line = w.predict(X);
	w.covariance = cov;
	return w;
}

/** The textbook implicit EKF update of the stacked constraint G(x) = 0
 * with noise R, H = dG/dx by central differences over the whole state,
 * computed densely from (x0, P0). */
struct DenseUpdate
{
	Eigen::VectorXd x, g;
	Eigen::MatrixXd P, S;
};
DenseUpdate denseImplicitEkf(const std::function<Eigen::VectorXd(const Eigen::VectorXd&)>& G,
	const Eigen::VectorXd& x0, const Eigen::MatrixXd& P0, const Eigen::MatrixXd& R)
{
	const Eigen::Index n = x0.size();
	DenseUpdate d;
	d.g = G(x0);
	Eigen::MatrixXd H(d.g.size(), n);
	for (Eigen::Index k = 0; k < n; k++)
	{
		Eigen::VectorXd a = x0, b = x0;
		a[k] += 1e-6;
		b[k] -= 1e-6;
		H.col(k) = (G(a) - G(b)) / 2e-6;
	}
	d.S = H * P0 * H.transpose() + R;
	const Eigen::MatrixXd K = P0 * H.transpose() * d.S.inverse();
	d.x = x0 - K * d.g;
	d.P = (Eigen::MatrixXd::Identity(n, n) - K * H) * P0;
	return d;
}
}  // namespace

TEST(EkfVerticalLandmarks, ConstraintJacobiansMatchFiniteDifferences)
{
	const Eigen::Vector3d X(0.4, -0.3, 0.8);
	const Eigen::Vector4d l(1.5, 4.0, 0.2, 1.9);
	for (const bool bothEnds : {true, false})
	{
		auto z = seen(X, l, 0.02, 0.01);
		z.position += Eigen::Vector2d(0.03, -0.05);	 // G != 0
		if (!bothEnds) z.sigmaLow = 0;
		const VerticalLandmarkConstraint g(z);
		ASSERT_EQ(g.size(), bothEnds ? 4 : 3);
		Eigen::MatrixXd GX, Gl;
		const Eigen::VectorXd g0 = g.evaluate(X, l, &GX, &Gl);
		const double eps = 1e-6;
		for (int k = 0; k < 3; k++)
		{
			Eigen::Vector3d a = X, b = X;
			a[k] += eps;
			b[k] -= eps;
			const Eigen::VectorXd fd = (g.evaluate(a, l) - g.evaluate(b, l)) / (2 * eps);
			EXPECT_LT((fd - GX.col(k)).norm(), 1e-8) << "robot " << k;
		}
		for (int k = 0; k < 4; k++)
		{
			Eigen::Vector4d a = l, b = l;
			a[k] += eps;
			b[k] -= eps;
			const Eigen::VectorXd fd = (g.evaluate(X, a) - g.evaluate(X, b)) / (2 * eps);
			EXPECT_LT((fd - Gl.col(k)).norm(), 1e-8) << "landmark " << k;
		}
		// The observed position's residual: the landmark seen from X, minus it.
		EXPECT_NEAR(g0[0], -0.03, 1e-12);
		EXPECT_NEAR(g0[1], 0.05, 1e-12);
	}
}

// The filter's update equals the textbook implicit EKF update (nu = -G,
// H = dG/dS by finite differences over the whole state, R = Sigma_L),
// computed densely from the state before.
TEST(EkfVerticalLandmarks, UpdateEqualsDenseEkfWithNumericJacobians)
{
	EkfLocalizer f;
	f.reset(gaussian(CPose2D(0, 0, 0.1), 0.04, 0.003));
	const Eigen::Vector4d l1(1.0, 4.0, 0.1, 1.8), l2(2.2, 4.0, 0.3, 2.0);
	f.updateVerticalLandmarks({startable({0, 0, 0.1}, l1, 0.03), startable({0, 0, 0.1}, l2, 0.04, 0, -1)});
	ASSERT_EQ(f.landmarkCount(), 2u);
	f.predict(gaussian(CPose2D(0.5, 0.1, 0.05), 0.01, 0.001));
	const Eigen::VectorXd x0 = f.state();
	const Eigen::MatrixXd P0 = f.covariance();
	std::vector<VerticalLandmarkObservation> z{
		seen({0.52, 0.1, 0.16}, l1, 0.03, 0.02), seen({0.52, 0.1, 0.16}, l2, 0.03, 0.02, 0, -1)};
	z[1].sigmaHigh = 0;	 // top end cut by the image border
	// Both on wall 0: one plane fit moves both (its error in R's cross terms).
	const Eigen::Matrix2d planeCov = Eigen::Vector2d(2e-4, 4e-5).asDiagonal();
	z[0].planeJacobian << 0.9, 0.4, 0.1, -0.2;
	z[1].planeJacobian << 0.8, 1.3, -0.1, 0.3;
	for (auto& o : z)
	{
		o.planeCovariance = planeCov;
		o.covariance += o.planeJacobian * planeCov * o.planeJacobian.transpose();
	}
	const auto u = f.updateVerticalLandmarks(z);
	ASSERT_EQ(u.used, 2u);

	auto G = [&](const Eigen::VectorXd& s) {
		Eigen::VectorXd out(7);
		const auto g1 = VerticalLandmarkConstraint(z[0]).evaluate(s.head<3>(), s.segment<4>(f.landmarkIndex(0)));
		const auto g2 = VerticalLandmarkConstraint(z[1]).evaluate(s.head<3>(), s.segment<4>(f.landmarkIndex(1)));
		out << g1, g2;
		return out;
	};
	Eigen::MatrixXd R = Eigen::MatrixXd::Zero(7, 7);
	R.block(0, 0, 4, 4) = VerticalLandmarkConstraint(z[0]).noise();
	R.block(4, 4, 3, 3) = VerticalLandmarkConstraint(z[1]).noise();
	R.block(0, 4, 2, 2) = z[0].planeJacobian * planeCov * z[1].planeJacobian.transpose();
	R.block(4, 0, 2, 2) = R.block(0, 4, 2, 2).transpose();
	const auto d = denseImplicitEkf(G, x0, P0, R);
	EXPECT_LT((f.state() - d.x).cwiseAbs().maxCoeff(), 1e-9);
	EXPECT_LT((f.covariance() - d.P).cwiseAbs().maxCoeff(), 1e-9);
	EXPECT_NEAR(u.jointMahalanobis2, d.g.dot(d.S.ldlt().solve(d.g)), 1e-6);
}

TEST(EkfVerticalLandmarks, WallPredictionJacobianMatchesFiniteDifferences)
{
	StereoWallObservation w;
	w.mapA = {-1.0, 3.5};
	w.mapB = {2.5, 4.2};
	w.origin = {0.1, 0.3};
	w.e = Eigen::Vector2d(0.2, -1).normalized();
	w.n = {-w.e.y(), w.e.x()};
	for (const Eigen::Vector3d& X : {Eigen::Vector3d(0.4, -0.3, 1.4), Eigen::Vector3d(-0.2, 0.5, 1.9)})
	{
		Eigen::Matrix<double, 2, 3> H;
		const Eigen::Vector2d h = w.predict(X, &H);
		for (int k = 0; k < 3; k++)
		{
			Eigen::Vector3d a = X, b = X;
			a[k] += 1e-6;
			b[k] -= 1e-6;
			EXPECT_LT(((w.predict(a) - w.predict(b)) / 2e-6 - H.col(k)).norm(), 1e-7) << k;
		}
		// The map's wall in the plane frame: its ends satisfy w = a + b s.
		for (const auto& p : {w.mapA, w.mapB})
		{
			const double c = std::cos(X.z()), s = std::sin(X.z());
			const Eigen::Vector2d d = p - X.head<2>();
			const Eigen::Vector2d pr(c * d.x() + s * d.y(), -s * d.x() + c * d.y());
			EXPECT_NEAR(w.n.dot(pr - w.origin), h.x() + h.y() * w.e.dot(pr - w.origin), 1e-12);
		}
	}
}

// A wall and the landmarks on it in one update: the filter's result equals
// the dense EKF whose R carries the wall fit's share of each landmark
// observation (Cov(position_i, fit) = J_i Sigma_ab).
TEST(EkfVerticalLandmarks, AWallAndItsLandmarksEqualTheDenseEkfWithTheirSharedFit)
{
	EkfLocalizer f;
	f.reset(gaussian(CPose2D(0, 0, 0.1), 0.04, 0.003));
	const Eigen::Vector4d l1(1.0, 4.0, 0.1, 1.8);
	f.updateVerticalLandmarks({startable({0, 0, 0.1}, l1, 0.03)});
	f.predict(gaussian(CPose2D(0.5, 0.1, 0.05), 0.01, 0.001));
	const Eigen::VectorXd x0 = f.state();
	const Eigen::MatrixXd P0 = f.covariance();
	const Eigen::Vector3d truth(0.52, 0.1, 0.16);
	const Eigen::Matrix2d planeCov = Eigen::Vector2d(2e-4, 4e-5).asDiagonal();
	auto z = seen(truth, l1, 0.03, 0.02);
	z.planeJacobian << 0.9, 0.4, 0.1, -0.2;
	z.planeCovariance = planeCov;
	z.covariance += z.planeJacobian * planeCov * z.planeJacobian.transpose();
	auto w = wallSeen(truth, planeCov);
	w.line += Eigen::Vector2d(0.01, -0.005);
	const auto u = f.updateVerticalLandmarks({z}, {w});
	ASSERT_EQ(u.used, 1u);
	ASSERT_EQ(u.wallsUsed, 1u);
	EXPECT_EQ(u.wallsObserved, 1u);

	// Stacked as the filter's nu = -G: landmark rows G = h - z, wall rows h - z.
	auto G = [&](const Eigen::VectorXd& s) {
		Eigen::VectorXd out(6);
		out << VerticalLandmarkConstraint(z).evaluate(s.head<3>(), s.segment<4>(f.landmarkIndex(0))),
			w.predict(s.head<3>()) - w.line;
		return out;
	};
	Eigen::MatrixXd R = Eigen::MatrixXd::Zero(6, 6);
	R.block(0, 0, 4, 4) = VerticalLandmarkConstraint(z).noise();
	R.block(4, 4, 2, 2) = planeCov;
	R.block(0, 4, 2, 2) = z.planeJacobian * planeCov;
	R.block(4, 0, 2, 2) = R.block(0, 4, 2, 2).transpose();
	const auto d = denseImplicitEkf(G, x0, P0, R);
	EXPECT_LT((f.state() - d.x).cwiseAbs().maxCoeff(), 1e-9);
	EXPECT_LT((f.covariance() - d.P).cwiseAbs().maxCoeff(), 1e-9);
}

// A wall observation tells the robot's distance to the wall and its heading
// to it, not where along the wall it is; one that disagrees with the map
// beyond its gate is not used.
TEST(EkfVerticalLandmarks, AWallObservesDistanceAndHeadingNotPositionAlongIt)
{
	EkfLocalizer f;
	const Eigen::Vector3d truth(0, 0, M_PI / 2);  // facing the wall y = 4
	f.reset(gaussian(CPose2D(0.05, -0.05, M_PI / 2 + 0.03), 0.01, 0.001));
	const Eigen::Matrix2d cov = Eigen::Vector2d(1e-6, 1e-7).asDiagonal();
	const auto u = f.updateVerticalLandmarks({}, {wallSeen(truth, cov)});
	EXPECT_EQ(u.wallsUsed, 1u);
	const auto r = f.robotPose();
	EXPECT_NEAR(r.mean.y(), 0, 0.003);
	EXPECT_NEAR(r.mean.phi(), M_PI / 2, 0.001);
	EXPECT_NEAR(r.mean.x(), 0.05, 0.005);  // along the wall: the prior's
	EXPECT_LT(r.cov(1, 1), 1.1e-6);	 // the wall's 1 mm
	EXPECT_NEAR(r.cov(0, 0), 0.01, 0.002);

	// 10 cm nearer the wall than the map says, 1 mm sigma: rejected.
	EkfLocalizer g;
	g.reset(gaussian(CPose2D(0, 0, M_PI / 2), 1e-6, 1e-8));
	auto off = wallSeen(truth, cov);
	off.line.x() -= 0.1;
	const auto v = g.updateVerticalLandmarks({}, {off});
	EXPECT_EQ(v.wallsUsed, 0u);
	EXPECT_EQ(v.wallsRejected, 1u);
	EXPECT_EQ(g.robotPose().mean.y(), 0.0);
}

TEST(EkfVerticalLandmarks, StartsOnTheWallUncorrelatedWithTheRobotAndConstrainsIt)
{
	EkfLocalizer f;
	// An uncertain robot: 0.3 m, 0.2 rad.
	f.reset(gaussian(CPose2D(0, 0, M_PI / 2), 0.09, 0.04));
	const Eigen::Vector4d l1(-1.0, 4.0, 0.0, 1.2), l2(1.2, 4.0, 0.5, 2.0);
	const Eigen::Vector3d X(0, 0, M_PI / 2);
	const auto u = f.updateVerticalLandmarks({startable(X, l1, 0.03), startable(X, l2, 0.03)});
	EXPECT_EQ(u.added, 2u);
	const auto lm = f.landmarks();
	ASSERT_EQ(lm.size(), 2u);
	EXPECT_TRUE(lm[0].vertical);
	EXPECT_LT((lm[0].mean - l1.head<2>()).norm(), 1e-12);
	EXPECT_NEAR(lm[0].lHigh, 1.2, 1e-12);
	// Eq. (17): along the wall only (the across-wall floor is 1 mm).
	EXPECT_NEAR(std::sqrt(lm[0].covariance(0, 0)), 0.03, 1e-9);
	EXPECT_LT(std::sqrt(lm[0].covariance(1, 1)), 1.01e-3);
	const Eigen::Index k = f.landmarkIndex(0);
	EXPECT_EQ(f.covariance().block(k, 0, 4, 3).cwiseAbs().maxCoeff(), 0.0);
	// Seen again from the same place: the robot learns where it is, most
	// of all across the wall (depth) where the landmarks are exact.
	f.predict(gaussian(CPose2D(0, 0, 0), 1e-6, 1e-8));
	const auto v = f.updateVerticalLandmarks({seen(X, l1, 0.02, 0.01), seen(X, l2, 0.02, 0.01)});
	EXPECT_EQ(v.used, 2u);
	EXPECT_EQ(v.added, 0u);
	const auto r = f.robotPose();
	EXPECT_LT(std::sqrt(r.cov(1, 1)), 0.03);  // across the wall: was 0.3 m
	EXPECT_LT(std::sqrt(r.cov(2, 2)), 0.02);  // heading: was 0.2 rad
	EXPECT_LT(std::sqrt(r.cov(0, 0)), 0.06);  // along: bounded by the landmarks' 3 cm
}

// Landmarks started in one frame from one boundary share its error:
// their cross-covariance is that boundary's part (section 3.3), not zero;
// another wall's boundary is another error.
TEST(EkfVerticalLandmarks, LandmarksStartedFromOneBoundaryShareItsError)
{
	EkfLocalizer f;
	f.reset(gaussian(CPose2D(0, 0, M_PI / 2), 0.01, 0.001));
	const Eigen::Vector3d X(0, 0, M_PI / 2);
	const Eigen::Matrix2d shared = Eigen::Vector2d(0.02 * 0.02, 0).asDiagonal();
	std::vector<VerticalLandmarkObservation> z{startable(X, {-1.0, 4.0, 0.2, 1.5}, 0.03),
		startable(X, {0.5, 4.0, 0.2, 1.5}, 0.03), startable(X, {2.0, 4.0, 0.2, 1.5}, 0.03, 1)};
	for (auto& o : z) o.startSharedCovariance = shared;
	f.updateVerticalLandmarks(z);
	ASSERT_EQ(f.landmarkCount(), 3u);
	const auto& P = f.covariance();
	const Eigen::Index k0 = f.landmarkIndex(0), k1 = f.landmarkIndex(1), k2 = f.landmarkIndex(2);
	EXPECT_LT((P.block<2, 2>(k0, k1) - shared).cwiseAbs().maxCoeff(), 1e-15);
	const double other02 = P.block<2, 2>(k0, k2).cwiseAbs().maxCoeff();
	const double other12 = P.block<2, 2>(k1, k2).cwiseAbs().maxCoeff();
	EXPECT_EQ(other02, 0.0);
	EXPECT_EQ(other12, 0.0);
	EXPECT_NEAR(P(k0, k0), 0.03 * 0.03, 1e-12);
	EXPECT_GT(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(P).eigenvalues().minCoeff(), -1e-15);
}

// With a match held (the keyframe's), the filter's belief lies the match's
// correction away from its state. A stereo pair is paired and linearized at
// the belief: fused then, it gives the posterior of committing the match
// first. The bug it fixes: the state was 10 cm and 2 deg off on moon-lab,
// and a line 30 cm from the one seen was paired.
TEST(EkfVerticalLandmarks, PairsAndLinearizesAtTheBeliefWhileAMatchIsHeld)
{
	const Eigen::Vector3d X0(0, 0, M_PI / 2);
	const Eigen::Vector4d l1(0.0, 4.0, 0.2, 1.5), l2(0.3, 4.0, 0.2, 1.5);
	auto build = [&]() {
		EkfLocalizer f;
		f.reset(gaussian(CPose2D(X0.x(), X0.y(), X0.z()), 1e-6, 1e-8));
		f.updateVerticalLandmarks({startable(X0, l1, 0.01), startable(X0, l2, 0.01)});
		// Odometry says 0.5 m ahead and 0.3 m to the left (world -x); the
		// robot went 0.5 m ahead: the state is 0.3 m off, the match exact.
		f.predict(gaussian(CPose2D(0.5, 0.3, 0), 0.04, 0.003));
		f.holdRelativeMotion(gaussian(CPose2D(0.5, 0.0, 0), 1e-4, 1e-5));
		return f;
	};
	const Eigen::Vector3d X(0, 0.5, M_PI / 2);
	// l2 seen from where the robot is; from the state it is where l1 is.
	const std::vector<VerticalLandmarkObservation> z{seen(X, l2, 0.01, 0.01)};
	EkfLocalizer held = build();
	ASSERT_GT((held.belief().x - held.state()).head<2>().norm(), 0.25);
	const auto u = held.updateVerticalLandmarks(z);
	EXPECT_EQ(u.landmarkOf, (std::vector<int>{1}));
	EkfLocalizer committed = build();
	committed.commitHeldMotion();
	const auto v = committed.updateVerticalLandmarks(z);
	EXPECT_EQ(v.landmarkOf, (std::vector<int>{1}));
	EXPECT_NEAR(u.jointMahalanobis2, v.jointMahalanobis2, 1e-3);
	const auto a = held.robotPose(), b = committed.robotPose();
	EXPECT_LT(std::hypot(a.mean.x() - b.mean.x(), a.mean.y() - b.mean.y()), 1e-4);
	EXPECT_LT(std::abs(a.mean.phi() - b.mean.phi()), 1e-5);
	EXPECT_LT((a.cov.asEigen() - b.cov.asEigen()).cwiseAbs().maxCoeff(), 1e-8);
	EXPECT_LT(std::hypot(a.mean.x() - X.x(), a.mean.y() - X.y()), 0.01);
}

TEST(EkfVerticalLandmarks, PairsOnlyOnItsWallWithItsPolarity)
{
	EkfLocalizer f;
	f.reset(gaussian(CPose2D(0, 0, M_PI / 2), 0.01, 0.001));
	const Eigen::Vector3d X(0, 0, M_PI / 2);
	const Eigen::Vector4d l(0.5, 4.0, 0.2, 1.5);
	f.updateVerticalLandmarks({startable(X, l, 0.03, 0, +1)});
	f.predict(gaussian(CPose2D(0, 0, 0), 1e-6, 1e-8));
	// The same place with the other polarity, or on another wall: no pair.
	auto u = f.updateVerticalLandmarks({seen(X, l, 0.02, 0.01, 0, -1), seen(X, l, 0.02, 0.01, 1, +1)});
	EXPECT_EQ(u.associated, 0u);
	EXPECT_EQ(u.landmarkOf, (std::vector<int>{-1, -1}));
	u = f.updateVerticalLandmarks({seen(X, l, 0.02, 0.01, 0, +1)});
	EXPECT_EQ(u.used, 1u);
	EXPECT_EQ(u.landmarkOf, (std::vector<int>{0}));
	// A selected feature inside its landmark's gate does not start another.
	u = f.updateVerticalLandmarks({startable(X, l + Eigen::Vector4d(0.08, 0, 0, 0), 0.03)});
	EXPECT_EQ(f.landmarkCount(), 1u);
}

TEST(EkfVerticalLandmarks, UsesTheLeastUncertainSubset)
{
	EkfLocalizer f;
	f.options.stereo_landmarks_per_frame = 2;
	f.reset(gaussian(CPose2D(0, 0, M_PI / 2), 0.01, 0.001));
	const Eigen::Vector3d X(0, 0, M_PI / 2);
	std::vector<VerticalLandmarkObservation> start, again;
	const double sigmas[4] = {0.08, 0.02, 0.05, 0.01};
	for (int k = 0; k < 4; k++)
	{
		const Eigen::Vector4d l(-1.5 + k, 4.0, 0.2, 1.5);
		start.push_back(startable(X, l, sigmas[k]));
		again.push_back(seen(X, l, 0.02, 0.01));
	}
	f.updateVerticalLandmarks(start);
	ASSERT_EQ(f.landmarkCount(), 4u);
	f.predict(gaussian(CPose2D(0, 0, 0), 1e-6, 1e-8));
	const auto u = f.updateVerticalLandmarks(again);
	EXPECT_EQ(u.associated, 4u);
	EXPECT_EQ(u.used, 2u);
	EXPECT_EQ(u.landmarkOf, (std::vector<int>{-1, 1, -1, 3}));
}

TEST(EkfVerticalLandmarks, RemovalBesidePointLandmarksKeepsEveryBlock)
{
	EkfLocalizer f;
	f.options.landmark_probation_steps = 1;
	f.reset(gaussian(CPose2D(0, 0, M_PI / 2), 0.01, 0.001));
	LandmarkObservation p;
	p.position = {3, 0};
	p.covariance = Eigen::Matrix2d::Identity() * 0.01;
	f.updateLandmarks({p});	 // point, seen once: pruned later
	const Eigen::Vector3d X(0, 0, M_PI / 2);
	const Eigen::Vector4d l(0.5, 4.0, 0.2, 1.5);
	f.updateVerticalLandmarks({startable(X, l, 0.03)});
	ASSERT_EQ(f.landmarkIndex(1), EkfLocalizer::kLandmarks + 2);
	f.predict(gaussian(CPose2D(0, 0, 0), 1e-6, 1e-8));
	f.updateVerticalLandmarks({seen(X, l, 0.02, 0.01)});  // seen twice: kept
	const Eigen::VectorXd before = f.state().segment<4>(f.landmarkIndex(1));
	// Two range-bearing frames without the point: its probation is over.
	f.updateLandmarks({});
	f.updateLandmarks({});
	ASSERT_EQ(f.landmarkCount(), 1u);
	EXPECT_EQ(f.landmarkIndex(0), EkfLocalizer::kLandmarks);
	EXPECT_EQ(f.state().size(), EkfLocalizer::kLandmarks + 4);
	EXPECT_LT((f.state().segment<4>(EkfLocalizer::kLandmarks) - before).norm(), 1e-15);
	EXPECT_TRUE(f.landmarks()[0].vertical);
}

// A 40 Hz laser predicts 16 times between two 2.5 Hz stereo pairs: a
// landmark's probation counts the pairs, or no stereo landmark would live to
// be seen twice (the bug: 176 started, none observed again).
TEST(EkfVerticalLandmarks, ProbationCountsTheStereoPairsNotThePredictions)
{
	EkfLocalizer f;
	f.options.landmark_probation_steps = 2;
	f.reset(gaussian(CPose2D(0, 0, M_PI / 2), 0.01, 0.001));
	const Eigen::Vector3d X(0, 0, M_PI / 2);
	const Eigen::Vector4d l(0.5, 4.0, 0.2, 1.5), other(-1.0, 4.0, 0.2, 1.5);
	f.updateVerticalLandmarks({startable(X, l, 0.03)});
	for (int k = 0; k < 16; k++) f.predict(gaussian(CPose2D(0, 0, 0), 1e-6, 1e-8));
	auto u = f.updateVerticalLandmarks({seen(X, l, 0.02, 0.01)});
	EXPECT_EQ(u.used, 1u);
	EXPECT_EQ(f.landmarkCount(), 1u);
	// Seen once and then missing from 3 pairs (probation 2): removed; the
	// one seen twice stays.
	f.updateVerticalLandmarks({startable(X, other, 0.03)});
	ASSERT_EQ(f.landmarkCount(), 2u);
	for (int pair = 0; pair < 3; pair++) f.updateVerticalLandmarks({});
	ASSERT_EQ(f.landmarkCount(), 1u);
	EXPECT_NEAR(f.state()[f.landmarkIndex(0)], 0.5, 0.05);
}

namespace
{
/** The robot drives 2 m along a wall with landmarks started on-line from
 * the first frame, odometry noise and observation noise drawn from the
 * models the filter is given; returns the robot's NEES at the end of the
 * run averaged over runs. With `shared`, the errors are those of the
 * extractor: the landmarks started in one frame share their boundary's
 * error along the wall (section 3.3), and the observations of one frame
 * share their plane fit's error (eq. 11), each declared to the filter
 * (startSharedCovariance, planeJacobian/planeCovariance); `declared`
 * false draws the same errors but declares them as independent. */
double monteCarloNees(bool shared, bool declared, bool wall = false)
{
	// Its own generator: MRPT's global one carries state (a cached Gaussian
	// draw) from earlier tests in the process past randomize(), which made
	// this test's draws depend on which tests ran before it.
	mrpt::random::CRandomGenerator rng(7);
	const int runs = 200, steps = 20;
	const double sOdo = 0.02, sYaw = 0.01, sObs = 0.02, sEnd = 0.02, sAlong = 0.03;
	// Shared parts: the boundary's along the wall, the plane fit's depth
	// offset a [m] and slope b of w = a + b s.
	const double sBoundary = shared ? 0.025 : 0, sPlaneA = shared ? 0.015 : 0, sPlaneB = shared ? 0.01 : 0;
	const Eigen::Matrix2d planeCov = Eigen::Vector2d(sPlaneA * sPlaneA, sPlaneB * sPlaneB).asDiagonal();
	std::vector<Eigen::Vector4d> truth;
	for (int k = 0; k < 5; k++) truth.emplace_back(-1.0 + 0.8 * k, 4.0, 0.1 * k, 1.5 + 0.1 * k);
	double nees = 0;
	for (int run = 0; run < runs; run++)
	{
		EkfLocalizer f;
		Eigen::Vector3d X(0, 0, M_PI / 2);	// true pose; the filter starts exact
		f.reset(gaussian(CPose2D(X.x(), X.y(), X.z()), 1e-8, 1e-10));
		std::vector<StereoWallObservation> walls;
		auto observe = [&](bool start) {
			std::vector<VerticalLandmarkObservation> z;
			const Eigen::Vector2d planeErr(rng.drawGaussian1D(0, sPlaneA), rng.drawGaussian1D(0, sPlaneB));
			const double boundaryErr = rng.drawGaussian1D(0, sBoundary);
			for (const auto& l : truth)
			{
				// The start position's error along the wall is common to the
				// landmark's life: drawn once per run (a landmark's start is
				// its eq. 15 estimate).
				auto o = start ? startable(X, l, sAlong) : seen(X, l, sObs, sEnd);
				// The plane fit moves the point across the wall (robot x,
				// facing it) by a + b s, s along the wall (robot y).
				Eigen::Matrix2d J = Eigen::Matrix2d::Zero();
				J(0, 0) = 1;
				J(0, 1) = o.position.y();
				o.position += Eigen::Vector2d(rng.drawGaussian1D(0, sObs), rng.drawGaussian1D(0, sObs)) + J * planeErr;
				o.covariance = Eigen::Matrix2d::Identity() * sObs * sObs + J * planeCov * J.transpose();
				if (declared)
				{
					o.planeJacobian = J;
					o.planeCovariance = planeCov;
				}
				o.lLow += rng.drawGaussian1D(0, sEnd);
				o.lHigh += rng.drawGaussian1D(0, sEnd);
				o.sigmaLow = o.sigmaHigh = sEnd;
				if (start)
				{
					o.start.x() += rng.drawGaussian1D(0, sAlong) + boundaryErr;
					const double v = sAlong * sAlong + sBoundary * sBoundary;
					o.startCovariance = Eigen::Vector2d(v, 0).asDiagonal();
					if (declared) o.startSharedCovariance = Eigen::Vector2d(sBoundary * sBoundary, 0).asDiagonal();
				}
				z.push_back(o);
			}
			// The wall's own fit: the same error the observations share.
			walls.clear();
			if (wall)
			{
				walls.push_back(wallSeen(X, planeCov));
				walls.back().line += planeErr;
			}
			return z;
		};
		f.updateVerticalLandmarks(observe(true));
		for (int s = 0; s < steps; s++)
		{
			// 0.1 m along the wall (robot frame: x ahead, here +90 deg, so
			// the robot drives sideways: y in its frame is the world's -x).
			const Eigen::Vector3d u(0, -0.1, 0);
			const Eigen::Vector3d noisy(
				u.x() + rng.drawGaussian1D(0, sOdo), u.y() + rng.drawGaussian1D(0, sOdo),
				u.z() + rng.drawGaussian1D(0, sYaw));
			const CPose2D next = CPose2D(X.x(), X.y(), X.z()) + CPose2D(noisy.x(), noisy.y(), noisy.z());
			X = {next.x(), next.y(), next.phi()};
			f.predict(gaussian(CPose2D(u.x(), u.y(), u.z()), sOdo * sOdo, sYaw * sYaw));
			const auto z = observe(false);
			f.updateVerticalLandmarks(z, walls);
		}
		const auto r = f.robotPose();
		Eigen::Vector3d e(r.mean.x() - X.x(), r.mean.y() - X.y(), mrpt::math::wrapToPi(r.mean.phi() - X.z()));
		nees += e.dot(r.cov.asEigen().ldlt().solve(e));
	}
	return nees / runs;
}

// 95% band of the mean of `runs` chi-square(3) draws.
std::pair<double, double> neesBand(int runs)
{
	return {mrpt::math::chi2inv(0.025, 3 * runs) / runs, mrpt::math::chi2inv(0.975, 3 * runs) / runs};
}
}  // namespace

TEST(EkfVerticalLandmarks, MonteCarloNeesIsConsistent)
{
	const auto [lo, hi] = neesBand(200);
	const double nees = monteCarloNees(false, false);
	EXPECT_GT(nees, lo);
	EXPECT_LT(nees, hi);
}

// The boundary error shared by the landmarks started in one frame and the
// plane fit shared by the observations of one frame: declared, the filter
// stays consistent; declared as independent (eq. 17 and eq. 14 alone), it
// counts each shared error once per feature and is overconfident.
TEST(EkfVerticalLandmarks, MonteCarloNeesIsConsistentWithSharedBoundaryAndPlaneErrors)
{
	const auto [lo, hi] = neesBand(200);
	const double nees = monteCarloNees(true, true);
	EXPECT_GT(nees, lo);
	EXPECT_LT(nees, hi);
	EXPECT_GT(monteCarloNees(true, false), hi);
}

// With the wall's own fit observed too (featloc's wall observations): still
// consistent when its error is declared shared with the observations
// constrained to it, overconfident when it is not.
TEST(EkfVerticalLandmarks, MonteCarloNeesIsConsistentWithTheWallFitObservedToo)
{
	const auto [lo, hi] = neesBand(200);
	const double nees = monteCarloNees(true, true, true);
	EXPECT_GT(nees, lo);
	EXPECT_LT(nees, hi);
	EXPECT_GT(monteCarloNees(true, false, true), hi);
}
