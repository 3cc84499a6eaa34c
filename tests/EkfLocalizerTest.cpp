// EkfLocalizer: prediction and updates against hand-computed values,
// Jacobians against finite differences, gating, landmark initialisation and
// joint-compatibility association among near-identical landmarks.
#include <gtest/gtest.h>
#include <mrpt/math/distributions.h>
#include <mrpt/poses/CPosePDFGaussian.h>

#include <Eigen/Dense>
#include <cmath>

#include "featloc/ekf/EkfLocalizer.h"
#include "featloc/ekf/JointCompatibilityBranchAndBound.h"
#include "featloc/ekf/LandmarkJointInnovation.h"
#include "featloc/math/DiagonalPoseGaussian.h"

using namespace featloc;
using mrpt::poses::CPose2D;
using mrpt::poses::CPosePDFGaussian;

namespace
{
CPosePDFGaussian gaussian(const CPose2D& mean, double vx, double vy, double vyaw)
{
	CPosePDFGaussian g;
	g.mean = mean;
	g.cov.setZero();
	g.cov(0, 0) = vx;
	g.cov(1, 1) = vy;
	g.cov(2, 2) = vyaw;
	return g;
}

LandmarkObservation observation(double x, double y, double sigma, int64_t id = -1)
{
	LandmarkObservation o;
	o.position = {x, y};
	o.covariance = Eigen::Matrix2d::Identity() * sigma * sigma;
	o.id = id;
	return o;
}
/** The filter of the hand-computed tests: no odometry direction offset in
 * play (tested on its own below). */
EkfOptions withoutDirectionOffset()
{
	EkfOptions o;
	o.odometry_direction_sigma = 0;
	return o;
}
}  // namespace

TEST(EkfLocalizer, AReadingsSamplingErrorIsTakenBackAtTheNextStep)
{
	// The odometry reading at the first scan may be off by e ~ N(0, s^2)
	// along the step (read early or late); the next reading is exact. The
	// robot after two steps is as certain as the odometry says (zero here):
	// e was taken back, not added up as a random walk would.
	EkfLocalizer f(withoutDirectionOffset());
	f.reset(gaussian(CPose2D(0, 0, 0), 0, 0, 0));
	mrpt::math::CMatrixDouble33 sampling;
	sampling(0, 0) = 0.01;
	f.predict(gaussian(CPose2D(1, 0, 0), 0, 0, 0), sampling);
	EXPECT_NEAR(f.robotPose().cov(0, 0), 0.01, 1e-12);
	f.predict(gaussian(CPose2D(1, 0, 0), 0, 0, 0));
	EXPECT_NEAR(f.robotPose().mean.x(), 2, 1e-12);
	EXPECT_NEAR(f.robotPose().cov(0, 0), 0, 1e-12);
	// A match that shows the first reading was 0.1 m long moves the robot
	// back, and the correction carries to the next step (e's mean).
	EkfLocalizer g(withoutDirectionOffset());
	g.reset(gaussian(CPose2D(0, 0, 0), 0, 0, 0));
	g.predict(gaussian(CPose2D(1, 0, 0), 1e-6, 1e-6, 1e-8), sampling);
	ASSERT_TRUE(g.updateRelativeMotion(gaussian(CPose2D(0.9, 0, 0), 1e-6, 1e-6, 1e-8)).used);
	EXPECT_NEAR(g.robotPose().mean.x(), 0.9, 1e-3);
	g.predict(gaussian(CPose2D(1, 0, 0), 1e-6, 1e-6, 1e-8));
	EXPECT_NEAR(g.robotPose().mean.x(), 2, 1e-3);  // 0.9 + 1 + the 0.1 taken back
}

TEST(EkfLocalizer, TheOdometryDirectionOffsetIsLearntFromTheMatches)
{
	// The odometry's steps point 3 deg to the right of the robot's true
	// motion (a scanner mounted 3 deg off): driving straight, each 0.5 m
	// step's translation disagrees with the (exact) match by 2.6 cm to the
	// side. The heading stays 0 throughout.
	const double beta = mrpt::DEG2RAD(3.0);
	const auto odometry = gaussian(CPose2D(0.5, 0, 0), 1e-4, 1e-4, mrpt::square(mrpt::DEG2RAD(0.5)));
	const CPose2D truth(0.5 * std::cos(beta), 0.5 * std::sin(beta), 0);
	// One match per keyframe interval of 4 steps: the sideways disagreement
	// of a step can be blamed on the heading at the steps before it.
	const auto match = gaussian(truth + truth + truth + truth, 4e-4, 4e-4, mrpt::square(mrpt::DEG2RAD(0.05)));
	auto drive = [&](EkfLocalizer& f) {
		f.reset(gaussian(CPose2D(0, 0, 0), 0, 0, 0));
		for (int i = 0; i < 80; ++i)
		{
			f.predict(odometry);
			if (i % 4 != 3) continue;
			EXPECT_TRUE(f.updateRelativeMotion(match).used) << "step " << i;
			f.cloneKeyframe();
		}
		return f.robotPose();
	};
	EkfOptions o;
	o.odometry_direction_sigma = mrpt::DEG2RAD(2.0);
	EkfLocalizer with(o), without(withoutDirectionOffset());
	const auto p = drive(with);
	const auto q = drive(without);
	EXPECT_NEAR(mrpt::RAD2DEG(with.state()[EkfLocalizer::kOdometryDirection]), 3.0, 0.2);
	EXPECT_LT(std::abs(mrpt::RAD2DEG(p.mean.phi())), 0.05);
	// Without b, the filter turns the robot a little at every match to
	// explain the steps' sideways disagreement.
	EXPECT_GT(std::abs(mrpt::RAD2DEG(q.mean.phi())), 0.05);
	EXPECT_LT(std::abs(p.mean.phi()), std::abs(q.mean.phi()) / 10);
	EXPECT_LT(std::abs(p.mean.y() - 40 * std::sin(beta)), 0.05);
}

TEST(EkfLocalizer, PredictionComposesOnSE2WithHandComputedCovariance)
{
	EkfLocalizer f(withoutDirectionOffset());
	// At (1, 2) heading +90 deg, P = diag(a, b, c); move 1 m forward.
	const double a = 0.01, b = 0.02, c = 0.003;
	f.reset(gaussian(CPose2D(1, 2, M_PI / 2), a, b, c));
	f.predict(gaussian(CPose2D(1, 0, 0), 0.04, 0.001, 0.0005));
	const auto p = f.robotPose();
	EXPECT_NEAR(p.mean.x(), 1, 1e-12);
	EXPECT_NEAR(p.mean.y(), 3, 1e-12);
	EXPECT_NEAR(p.mean.phi(), M_PI / 2, 1e-12);
	// J_x = [1 0 -1; 0 1 0; 0 0 1] (d/dyaw of the rotated step (-sin, cos)
	// * 1 m = (-1, 0)), J_u = rotation by 90 deg: the step's forward
	// variance goes to y, its lateral variance to x.
	Eigen::Matrix3d expected;
	expected << a + c + 0.001, 0, -c, 0, b + 0.04, 0, -c, 0, c + 0.0005;
	EXPECT_LT((p.cov.asEigen() - expected).cwiseAbs().maxCoeff(), 1e-12) << p.cov;
	// The clone stays where it was, still fully correlated with the old
	// pose: cov(robot, clone) = J_x P.
	const Eigen::MatrixXd& P = f.covariance();
	EXPECT_NEAR(P(0, 3), a, 1e-12);
	EXPECT_NEAR(P(0, 5), -c, 1e-12);
	EXPECT_NEAR(P(1, 4), b, 1e-12);
}

TEST(EkfLocalizer, MatchUpdateIsTheScalarKalmanUpdateWhenTheCloneIsCertain)
{
	EkfLocalizer f(withoutDirectionOffset());
	f.reset(gaussian(CPose2D(0, 0, 0), 0, 0, 0));
	f.predict(gaussian(CPose2D(1, 0, 0), 0.04, 0.04, 0.0004));
	// The matcher says 1.1 m with variance 0.01: gain 0.04 / 0.05 = 0.8.
	const auto u = f.updateRelativeMotion(gaussian(CPose2D(1.1, -0.05, 0.01), 0.01, 0.01, 0.0001));
	ASSERT_TRUE(u.used) << u.reason;
	const auto p = f.robotPose();
	EXPECT_NEAR(p.mean.x(), 1.08, 1e-9);
	EXPECT_NEAR(p.mean.y(), -0.04, 1e-9);
	EXPECT_NEAR(p.mean.phi(), 0.008, 1e-9);
	EXPECT_NEAR(p.cov(0, 0), 0.008, 1e-12);
	EXPECT_NEAR(p.cov(1, 1), 0.008, 1e-12);
	EXPECT_NEAR(p.cov(2, 2), 0.00008, 1e-12);
	// Mahalanobis^2 of the innovation (0.1, -0.05, 0.01) under S = diag(0.05,
	// 0.05, 0.0005).
	EXPECT_NEAR(u.mahalanobis2, 0.01 / 0.05 + 0.0025 / 0.05 + 0.0001 / 0.0005, 1e-9);
}

TEST(EkfLocalizer, MatchUpdateCorrectsAnUncertainKeyframeToo)
{
	// Clone and robot equally uncertain and fully correlated: a relative
	// motion says nothing about where the keyframe was, only about the
	// motion since, so the robot's covariance cannot drop below the
	// clone's.
	EkfLocalizer f;
	f.reset(gaussian(CPose2D(0, 0, 0), 0.5, 0.5, 0.01));
	f.predict(gaussian(CPose2D(1, 0, 0), 0.04, 0.04, 0.0004));
	ASSERT_TRUE(f.updateRelativeMotion(gaussian(CPose2D(1, 0, 0), 1e-8, 1e-8, 1e-10)).used);
	const auto r = f.robotPose(), k = f.keyframePose();
	EXPECT_GE(r.cov(0, 0), k.cov(0, 0) - 1e-9);
	// ... and with an almost exact match the robot is exactly the keyframe
	// moved by it: the motion's own uncertainty is gone.
	const Eigen::MatrixXd& P = f.covariance();
	const double varMotionX = P(0, 0) + P(3, 3) - 2 * P(0, 3);
	EXPECT_LT(varMotionX, 1e-7);
}

TEST(EkfLocalizer, ObservationJacobiansMatchFiniteDifferences)
{
	EkfLocalizer f;
	f.reset(gaussian(CPose2D(0.3, -0.2, 0.7), 0.01, 0.01, 0.001));
	f.updateLandmarks({observation(2.0, 1.0, 0.05)});
	ASSERT_EQ(f.landmarkCount(), 1u);
	f.predict(gaussian(CPose2D(0.5, 0.1, 0.3), 0.01, 0.01, 0.001));
	Eigen::Matrix<double, 2, 3> Hr;
	Eigen::Matrix2d Hl;
	const Eigen::Vector2d h0 = f.predictObservation(0, &Hr, &Hl);
	// Perturb the state through a copy with a moved robot / landmark: the
	// observation of the landmark from the moved robot.
	const Eigen::VectorXd x = f.state();
	auto observe = [&](const Eigen::VectorXd& s) {
		const double c = std::cos(s[2]), sn = std::sin(s[2]);
		const Eigen::Vector2d d = s.segment<2>(f.landmarkIndex(0)) - s.segment<2>(0);
		return Eigen::Vector2d(c * d.x() + sn * d.y(), -sn * d.x() + c * d.y());
	};
	EXPECT_LT((observe(x) - h0).norm(), 1e-12);
	const double eps = 1e-7;
	for (int k = 0; k < 3; k++)
	{
		Eigen::VectorXd xp = x;
		xp[k] += eps;
		EXPECT_LT(((observe(xp) - h0) / eps - Hr.col(k)).norm(), 1e-5) << "robot " << k;
	}
	for (int k = 0; k < 2; k++)
	{
		Eigen::VectorXd xp = x;
		xp[f.landmarkIndex(0) + k] += eps;
		EXPECT_LT(((observe(xp) - h0) / eps - Hl.col(k)).norm(), 1e-5) << "landmark " << k;
	}
}

TEST(EkfLocalizer, MatchFarFromThePredictionIsGatedWithAReason)
{
	EkfLocalizer f;
	f.reset(gaussian(CPose2D(0, 0, 0), 0, 0, 0));
	f.predict(gaussian(CPose2D(1, 0, 0), 0.0004, 0.0004, 1e-5));
	const auto before = f.robotPose();
	const auto u = f.updateRelativeMotion(gaussian(CPose2D(1.5, 0, 0), 0.0004, 0.0004, 1e-5));
	EXPECT_FALSE(u.used);
	EXPECT_GT(u.mahalanobis2, f.options.matcher_gate_chi2);
	EXPECT_NE(u.reason.find("Mahalanobis^2"), std::string::npos) << u.reason;
	EXPECT_NE(u.reason.find("0.500 m"), std::string::npos) << u.reason;
	EXPECT_EQ(f.robotPose().mean, before.mean);	 // nothing changed
}

TEST(EkfLocalizer, LandmarkIsInitialisedByTheInverseModelAndRefinedByReobservation)
{
	EkfLocalizer f;
	// Certain robot at (1, 1) heading 90 deg; a landmark 2 m ahead.
	f.reset(gaussian(CPose2D(1, 1, M_PI / 2), 0, 0, 0));
	LandmarkObservation o;
	o.position = {2, 0};
	o.covariance << 0.01, 0.002, 0.002, 0.04;
	const auto u1 = f.updateLandmarks({o});
	EXPECT_EQ(u1.added, 1u);
	auto l = f.landmarks();
	ASSERT_EQ(l.size(), 1u);
	EXPECT_NEAR(l[0].mean.x(), 1, 1e-12);
	EXPECT_NEAR(l[0].mean.y(), 3, 1e-12);
	// Robot-frame covariance rotated by 90 deg: x' = -y, y' = x.
	EXPECT_NEAR(l[0].covariance(0, 0), 0.04, 1e-12);
	EXPECT_NEAR(l[0].covariance(1, 1), 0.01, 1e-12);
	EXPECT_NEAR(l[0].covariance(0, 1), -0.002, 1e-12);
	// The same observation again: two equal measurements halve the
	// covariance and leave the mean.
	const auto u2 = f.updateLandmarks({o});
	EXPECT_EQ(u2.associated, 1u);
	EXPECT_EQ(u2.added, 0u);
	l = f.landmarks();
	ASSERT_EQ(l.size(), 1u);
	EXPECT_NEAR(l[0].mean.y(), 3, 1e-12);
	EXPECT_NEAR(l[0].covariance(0, 0), 0.02, 1e-12);
	EXPECT_NEAR(l[0].covariance(1, 1), 0.005, 1e-12);
	EXPECT_EQ(l[0].observations, 2u);
}

TEST(EkfLocalizer, LandmarkSeenOnceIsRemovedAfterProbation)
{
	EkfLocalizer f;
	f.options.landmark_probation_steps = 3;
	f.reset(gaussian(CPose2D(0, 0, 0), 0, 0, 0));
	f.updateLandmarks({observation(2, 0, 0.05), observation(0, 3, 0.05)});
	for (int k = 0; k < 3; k++)
	{
		f.predict(gaussian(CPose2D(0, 0, 0), 1e-6, 1e-6, 1e-8));
		f.updateLandmarks({observation(2, 0, 0.05)});  // only the first again
	}
	EXPECT_EQ(f.landmarkCount(), 2u);
	// Predictions alone do not end it: probation counts the sensor's frames.
	for (int k = 0; k < 20; k++) f.predict(gaussian(CPose2D(0, 0, 0), 1e-6, 1e-6, 1e-8));
	EXPECT_EQ(f.landmarkCount(), 2u);
	f.updateLandmarks({});	// the fourth frame without it
	ASSERT_EQ(f.landmarkCount(), 1u);
	EXPECT_NEAR(f.landmarks()[0].mean.x(), 2, 1e-3);
	EXPECT_EQ(f.state().size(), EkfLocalizer::kLandmarks + 2);
	EXPECT_EQ(f.covariance().rows(), EkfLocalizer::kLandmarks + 2);
}

TEST(EkfLocalizer, KnownIdentityPairsEvenWhenAnotherLandmarkIsNearer)
{
	EkfLocalizer f;
	f.reset(gaussian(CPose2D(0, 0, 0), 0, 0, 0));
	f.updateLandmarks({observation(3, 0, 0.05, 7), observation(3, 0.3, 0.05, 8)});
	ASSERT_EQ(f.landmarkCount(), 2u);
	const auto u = f.updateLandmarks({observation(3, 0.28, 0.05, 8)});
	EXPECT_EQ(u.associated, 1u);
	const auto l = f.landmarks();
	EXPECT_EQ(l[0].observations, 1u);
	EXPECT_EQ(l[1].observations, 2u);
	EXPECT_EQ(l[1].id, 8);
}

// Two landmarks 0.3 m apart, the robot 0.3 m off to the side of where the
// filter believes (sigma 0.3 m across): each observation is individually
// compatible with both landmarks, and nearest neighbour pairs the first
// one with the wrong landmark. The joint test sees that one common offset
// explains both observations only with the right pairing.
TEST(EkfLocalizer, JcbbSeparatesNearIdenticalLandmarksWhereNearestNeighbourFails)
{
	auto run = [](const std::string& method) {
		EkfLocalizer f;
		f.options.data_association = method;
		f.reset(gaussian(CPose2D(0, 0, 0), 1e-8, 1e-8, 1e-10));
		f.updateLandmarks({observation(5, 0, 0.01), observation(5, 0.3, 0.01)});
		// The robot drifts sideways by -0.3 m; the filter predicts no motion
		// with 0.3 m sigma across.
		f.predict(gaussian(CPose2D(0, 0, 0), 1e-6, 0.09, 1e-8));
		// From y = -0.3 the landmarks appear 0.3 m further left.
		f.updateLandmarks({observation(5, 0.3, 0.01), observation(5, 0.6, 0.01)});
		return f;
	};
	const EkfLocalizer jcbb = run("jcbb");
	EXPECT_NEAR(jcbb.robotPose().mean.y(), -0.3, 0.01);
	auto l = jcbb.landmarks();
	ASSERT_EQ(l.size(), 2u);
	EXPECT_NEAR(l[0].mean.y(), 0, 0.01);
	EXPECT_NEAR(l[1].mean.y(), 0.3, 0.01);
	EXPECT_EQ(l[0].observations, 2u);
	EXPECT_EQ(l[1].observations, 2u);

	// Nearest neighbour pairs the first observation with the second
	// landmark (a perfect fit on its own), then the second with the first:
	// the map is corrupted (the landmarks pulled together).
	const EkfLocalizer nn = run("nearest");
	l = nn.landmarks();
	ASSERT_EQ(l.size(), 2u);
	EXPECT_LT(std::abs(l[1].mean.y() - l[0].mean.y()), 0.2)
		<< "nearest neighbour was expected to be fooled in this scene";
}

TEST(JointCompatibilityBranchAndBound, PrefersMorePairsThenSmallerDistance)
{
	// Two observations, two landmarks, every pairing individually fine;
	// only (0->1, 1->0) is jointly compatible.
	const auto best = JointCompatibilityBranchAndBound::solve(
		{{0, 1}, {0, 1}},
		[](const std::vector<std::pair<size_t, size_t>>& pairs) {
			double d = 0;
			for (const auto& [i, j] : pairs) d += (i == j) ? 5.0 : 0.5;
			return d;
		},
		[](size_t k) { return mrpt::math::chi2inv(0.99, static_cast<unsigned>(2 * k)); });
	ASSERT_EQ(best.size(), 2u);
	EXPECT_EQ(best[0], 1);
	EXPECT_EQ(best[1], 0);
}

// A known identity whose innovation fails the individual gate is not fused,
// whatever the association mode (issue: nearest neighbour used to fuse it).
TEST(EkfLocalizer, GatedOutKnownIdentityIsNotFusedInEitherMode)
{
	for (const char* mode : {"nearest", "jcbb"})
	{
		EkfOptions o;
		o.data_association = mode;
		EkfLocalizer f(o);
		f.reset(gaussian(CPose2D(0, 0, 0), 0, 0, 0));
		f.updateLandmarks({observation(3, 0, 0.05, 7), observation(0, 4, 0.05, -1)});
		ASSERT_EQ(f.landmarkCount(), 2u);
		const Eigen::VectorXd before = f.state();
		// Landmark 7 seen 2 m from where it is: implausible at 5 cm sigma.
		const auto u = f.updateLandmarks({observation(5, 0, 0.05, 7)});
		EXPECT_EQ(u.rejected, 1u) << mode;
		EXPECT_EQ(u.associated, 0u) << mode;
		EXPECT_EQ(u.added, 0u) << mode;
		EXPECT_TRUE(f.state().isApprox(before)) << mode;
		EXPECT_EQ(f.landmarks()[0].observations, 1u) << mode;
	}
}

// Removing a landmark from the middle of the state (probation) shifts the
// others without touching their variances or their correlations with each
// other and with the robot.
TEST(EkfLocalizer, RemovingALandmarkInTheMiddleKeepsTheOthersCovariances)
{
	EkfLocalizer f;
	f.options.landmark_probation_steps = 2;
	f.reset(gaussian(CPose2D(0, 0, 0), 0.01, 0.01, 0.001));
	f.updateLandmarks({observation(2, 0, 0.05, 0), observation(0, 3, 0.05, 1),
		observation(-2, 1, 0.05, 2)});
	ASSERT_EQ(f.landmarkCount(), 3u);
	// Landmarks 0 and 2 seen again (correlated through the robot), 1 not.
	f.predict(gaussian(CPose2D(0.1, 0, 0), 1e-4, 1e-4, 1e-5));
	f.updateLandmarks({observation(1.9, 0, 0.05, 0), observation(-2.1, 1, 0.05, 2)});
	f.updateLandmarks({});
	ASSERT_EQ(f.landmarkCount(), 3u);
	const Eigen::MatrixXd before = f.covariance();
	const Eigen::VectorXd xBefore = f.state();
	f.updateLandmarks({});	// probation of landmark 1 ends (its third frame after)
	ASSERT_EQ(f.landmarkCount(), 2u);
	const Eigen::MatrixXd after = f.covariance();
	// Old indices of the kept rows: robot, clones, landmark 0, landmark 2.
	std::vector<Eigen::Index> keep;
	const Eigen::Index second = EkfLocalizer::kLandmarks + 2, third = EkfLocalizer::kLandmarks + 4;
	for (Eigen::Index i = 0; i < second; i++) keep.push_back(i);
	keep.push_back(third);
	keep.push_back(third + 1);
	ASSERT_EQ(static_cast<Eigen::Index>(keep.size()), after.rows());
	EXPECT_LT((after - before(keep, keep)).cwiseAbs().maxCoeff(), 1e-15);
	EXPECT_LT((f.state() - xBefore(keep)).cwiseAbs().maxCoeff(), 1e-15);
	EXPECT_EQ(f.landmarks()[1].id, 2);
	EXPECT_NE(before(EkfLocalizer::kLandmarks, third), 0.0);
}

// The scan-match measurement h = x_c^-1 (+) x_a: its Jacobians in the
// measured pose and in the keyframe clone against finite differences.
TEST(EkfLocalizer, RelativeMotionJacobiansMatchFiniteDifferences)
{
	EkfLocalizer f;
	f.reset(gaussian(CPose2D(0.3, -0.2, 0.7), 0.01, 0.01, 0.001));
	f.predict(gaussian(CPose2D(0.8, 0.3, -0.4), 0.01, 0.01, 0.001));
	Eigen::Matrix3d Ha, Hc;
	const Eigen::Vector3d h0 = f.predictRelativeMotion(EkfLocalizer::kRobot, &Ha, &Hc);
	const Eigen::VectorXd x = f.state();
	auto relative = [](const Eigen::VectorXd& s) {
		const CPose2D c(s[3], s[4], s[5]), a(s[0], s[1], s[2]);
		const CPose2D d = a - c;
		return Eigen::Vector3d(d.x(), d.y(), d.phi());
	};
	EXPECT_LT((relative(x) - h0).norm(), 1e-12);
	EXPECT_NEAR(h0.x(), 0.8, 1e-12);
	EXPECT_NEAR(h0.z(), -0.4, 1e-12);
	const double eps = 1e-7;
	for (int k = 0; k < 3; k++)
	{
		Eigen::VectorXd xa = x, xc = x;
		xa[EkfLocalizer::kRobot + k] += eps;
		xc[EkfLocalizer::kClone + k] += eps;
		EXPECT_LT(((relative(xa) - h0) / eps - Ha.col(k)).norm(), 1e-5) << "pose " << k;
		EXPECT_LT(((relative(xc) - h0) / eps - Hc.col(k)).norm(), 1e-5) << "clone " << k;
	}
}

// A held match is the same information as the match fused at once: the
// views equal the immediate update, and committing it later (after more
// motion and landmarks) gives the filter that fused it at its own time.
TEST(EkfLocalizer, HeldMatchEqualsTheMatchFusedAtItsTime)
{
	const auto z = gaussian(CPose2D(1.05, 0.02, 0.01), 1e-4, 1e-4, 1e-5);
	EkfLocalizer held, now;
	for (EkfLocalizer* f : {&held, &now})
	{
		f->reset(gaussian(CPose2D(0, 0, 0), 0.01, 0.01, 0.001));
		f->updateLandmarks({observation(2, 1, 0.05, 4)});
		f->predict(gaussian(CPose2D(1, 0, 0), 0.01, 0.01, 0.001));
	}
	ASSERT_TRUE(held.testRelativeMotion(z).used);
	held.holdRelativeMotion(z);
	ASSERT_TRUE(now.updateRelativeMotion(z).used);
	auto near = [](const CPosePDFGaussian& a, const CPosePDFGaussian& b) {
		return (a.mean.asVectorVal() - b.mean.asVectorVal()).norm() < 1e-9 &&
			(a.cov.asEigen() - b.cov.asEigen()).cwiseAbs().maxCoeff() < 1e-12;
	};
	EXPECT_TRUE(near(held.robotPose(), now.robotPose()));
	EXPECT_TRUE(near(held.keyframePose(), now.keyframePose()));
	EXPECT_LT((held.landmarks()[0].mean - now.landmarks()[0].mean).norm(), 1e-9);
	EXPECT_LT((held.landmarks()[0].covariance - now.landmarks()[0].covariance).norm(), 1e-12);
	// Time passes (uncertainty grows, no motion: a linear prediction, so
	// the order of prediction and update cannot matter), then the keyframe
	// changes: the held match is fused against the pose it measured,
	// exactly as if fused at its time.
	for (EkfLocalizer* f : {&held, &now})
		for (int k = 0; k < 3; k++) f->predict(gaussian(CPose2D(0, 0, 0), 0.01, 0.01, 0.001));
	held.cloneKeyframe();
	now.cloneKeyframe();
	EXPECT_FALSE(held.hasHeldMotion());
	// (The match clone's slot is scratch space and differs.)
	std::vector<Eigen::Index> idx{0, 1, 2, 3, 4, 5};
	for (Eigen::Index i = EkfLocalizer::kLandmarks; i < held.state().size(); i++)
		idx.push_back(i);
	const Eigen::MatrixXd Ph = held.covariance(), Pn = now.covariance();
	EXPECT_LT((held.state()(idx) - now.state()(idx)).cwiseAbs().maxCoeff(), 1e-9);
	EXPECT_LT((Ph(idx, idx) - Pn(idx, idx)).cwiseAbs().maxCoeff(), 1e-12);
}

// JCBB's incremental joint distance equals the one computed from the whole
// stacked innovation, for growing and shrinking hypotheses.
TEST(EkfLocalizer, IncrementalJointDistanceEqualsTheStackedOne)
{
	EkfLocalizer f;
	f.reset(gaussian(CPose2D(0, 0, 0), 0.02, 0.02, 0.002));
	std::vector<LandmarkObservation> first;
	for (int k = 0; k < 5; k++) first.push_back(observation(1 + k, 0.5 * k - 1, 0.05));
	f.updateLandmarks(first);
	ASSERT_EQ(f.landmarkCount(), 5u);
	f.predict(gaussian(CPose2D(0.3, 0.1, 0.05), 0.01, 0.01, 0.001));
	// A held match: the distances are against the belief, not the state.
	f.holdRelativeMotion(gaussian(CPose2D(0.27, 0.12, 0.04), 0.005, 0.005, 0.001));
	const EkfLocalizer::Belief b = f.belief();
	ASSERT_GT((b.x - f.state()).norm(), 0.01);
	std::vector<LandmarkObservation> obs;
	for (int k = 0; k < 5; k++) obs.push_back(observation(0.75 + k, 0.5 * k - 1.1, 0.05));
	// The stacked distance, computed densely.
	auto dense = [&](const std::vector<std::pair<size_t, size_t>>& pairs) {
		const Eigen::Index m = 2 * static_cast<Eigen::Index>(pairs.size());
		const Eigen::Index n = f.state().size();
		Eigen::MatrixXd H = Eigen::MatrixXd::Zero(m, n), R = Eigen::MatrixXd::Zero(m, m);
		Eigen::VectorXd nu(m);
		for (size_t a = 0; a < pairs.size(); a++)
		{
			Eigen::Matrix<double, 2, 3> Hr;
			Eigen::Matrix2d Hl;
			const auto h = f.predictObservation(b.x, pairs[a].second, &Hr, &Hl);
			const Eigen::Index r = 2 * static_cast<Eigen::Index>(a);
			H.block<2, 3>(r, 0) = Hr;
			H.block<2, 2>(r, f.landmarkIndex(pairs[a].second)) = Hl;
			nu.segment<2>(r) = obs[pairs[a].first].position - h;
			R.block<2, 2>(r, r) = obs[pairs[a].first].covariance;
		}
		const Eigen::MatrixXd S = H * b.P * H.transpose() + R;
		return nu.dot(S.ldlt().solve(nu));
	};
	LandmarkJointInnovation joint(f, b, obs);
	std::vector<std::pair<size_t, size_t>> pairs;
	const std::vector<std::pair<size_t, size_t>> order{{0, 0}, {1, 1}, {2, 3}, {3, 3}, {4, 4}};
	for (const auto& [i, j] : order)
	{
		pairs.emplace_back(i, j);
		const double d = joint.push(i, j);
		EXPECT_NEAR(d, dense(pairs), 1e-8 * (1 + d)) << pairs.size() << " pairs";
	}
	joint.pop();
	joint.pop();
	pairs.resize(3);
	EXPECT_NEAR(joint.distance(), dense(pairs), 1e-8);
	EXPECT_NEAR(joint.push(4, 2), (pairs.emplace_back(4, 2), dense(pairs)), 1e-8);
}

