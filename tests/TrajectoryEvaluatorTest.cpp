#include <gtest/gtest.h>
#include <mrpt/core/bits_math.h>
#include <mrpt/poses/CPose2D.h>

#include <cmath>
#include <fstream>

#include "featloc/core/InputError.h"
#include "featloc/eval/ErrorStats.h"
#include "featloc/eval/TrajectoryEvaluator.h"
#include "featloc/eval/TrajectoryFile.h"
#include "support/TempDir.h"

using namespace featloc;
using featloc::test::TempDir;
using mrpt::poses::CPose2D;

namespace
{
/** A loop of n poses at 10 Hz starting at t0. */
Trajectory loop(size_t n, double t0 = 100.0)
{
	Trajectory t;
	t.source = "gt";
	for (size_t i = 0; i < n; i++)
	{
		const double a = 2 * M_PI * static_cast<double>(i) / static_cast<double>(n);
		TimedPose p;
		p.t = t0 + 0.1 * static_cast<double>(i);
		p.pose = {5 * std::cos(a), 3 * std::sin(a), a + M_PI / 2};
		t.poses.push_back(p);
	}
	return t;
}

Trajectory transformed(const Trajectory& in, const CPose2D& T)
{
	Trajectory out = in;
	out.source = "est";
	for (auto& p : out.poses) p.pose = (T + CPose2D(p.pose)).asTPose();
	return out;
}
}  // namespace

TEST(ErrorStats, KnownPercentilesAndMoments)
{
	const ErrorStats s = ErrorStats::of({4, 1, 3, 2, 5});
	EXPECT_EQ(s.count, 5u);
	EXPECT_DOUBLE_EQ(s.mean, 3);
	EXPECT_DOUBLE_EQ(s.median, 3);
	EXPECT_DOUBLE_EQ(s.p95, 4.8);  // 4 + 0.8 * (5 - 4), numpy's default
	EXPECT_DOUBLE_EQ(s.max, 5);
	EXPECT_DOUBLE_EQ(s.rmse, std::sqrt(11.0));
	EXPECT_DOUBLE_EQ(s.stddev, std::sqrt(2.0));
	EXPECT_EQ(ErrorStats::of({}).count, 0u);
}

TEST(TrajectoryEvaluator, RigidlyMovedCopyHasZeroErrorAndTheInverseAlignment)
{
	const Trajectory gt = loop(200, 1.5e9);	 // epoch-sized times and floats
	const CPose2D T(10.0, -4.0, 0.7);
	const Trajectory est = transformed(gt, T);
	const EvaluationReport r = TrajectoryEvaluator(0.02).evaluate(gt, est);
	EXPECT_EQ(r.associated, 200u);
	// The alignment goes through float correspondences (mrpt::tfest).
	EXPECT_LT(r.ate.max, 1e-5);
	EXPECT_LT(r.ateRotation.max, 1e-6);
	EXPECT_LT(r.rpeTranslation.max, 1e-9);
	EXPECT_LT(r.rpeRotation.max, 1e-9);
	const CPose2D inv = CPose2D() - T;
	EXPECT_NEAR(r.alignment.x, inv.x(), 1e-5);
	EXPECT_NEAR(r.alignment.y, inv.y(), 1e-5);
	EXPECT_NEAR(r.alignment.phi, inv.phi(), 1e-7);
}

TEST(TrajectoryEvaluator, KnownAteAndRpe)
{
	// Estimate = a straight ground truth with lateral offsets +d -d -d +d
	// repeated: balanced, so the best alignment is the identity and every
	// ATE error is d; consecutive RPE errors are 2d on the 50 sign changes
	// among 99 pairs, 0 elsewhere.
	Trajectory gt, est;
	gt.source = "gt";
	est.source = "est";
	const double d = 0.05;
	for (int i = 0; i < 100; i++)
	{
		TimedPose p;
		p.t = i * 0.1;
		p.pose = {0.1 * i, 0, 0};
		gt.poses.push_back(p);
		p.pose.y = (i % 4 == 0 || i % 4 == 3) ? d : -d;
		est.poses.push_back(p);
	}
	const EvaluationReport r = TrajectoryEvaluator(0.02).evaluate(gt, est);
	EXPECT_NEAR(r.ate.rmse, d, 1e-6);
	EXPECT_NEAR(r.ate.max, d, 1e-6);
	EXPECT_NEAR(r.rpeTranslation.mean, 50 * 2 * d / 99, 1e-9);
	EXPECT_NEAR(r.rpeTranslation.max, 2 * d, 1e-9);
	EXPECT_NEAR(r.rpeRotation.max, 0, 1e-12);
}

TEST(TrajectoryEvaluator, RotationDriftShowsInRpeRotation)
{
	// Each estimated step turns 0.5 deg more than the truth.
	Trajectory gt, est;
	gt.source = est.source = "x";
	CPose2D g, e;
	for (int i = 0; i < 50; i++)
	{
		TimedPose p;
		p.t = i;
		p.pose = g.asTPose();
		gt.poses.push_back(p);
		p.pose = e.asTPose();
		est.poses.push_back(p);
		g = g + CPose2D(0.2, 0, 0.01);
		e = e + CPose2D(0.2, 0, 0.01 + mrpt::DEG2RAD(0.5));
	}
	const EvaluationReport r = TrajectoryEvaluator(0.02).evaluate(gt, est);
	EXPECT_NEAR(r.rpeRotation.mean, mrpt::DEG2RAD(0.5), 1e-9);
	EXPECT_NEAR(r.rpeTranslation.mean, 0, 1e-9);
	EXPECT_GT(r.ate.rmse, 0.1);
}

TEST(TrajectoryEvaluator, AssociationIsNearestUniqueWithinTolerance)
{
	Trajectory gt, est;
	for (double t : {0.0, 1.0, 2.0, 3.0})
	{
		TimedPose p;
		p.t = t;
		gt.poses.push_back(p);
	}
	for (double t : {0.005, 0.012, 1.5, 2.019, 3.03})
	{
		TimedPose p;
		p.t = t;
		est.poses.push_back(p);
	}
	const auto pairs = TrajectoryEvaluator(0.02).associate(gt, est);
	ASSERT_EQ(pairs.size(), 2u);
	EXPECT_EQ(pairs[0], std::make_pair(size_t(0), size_t(0)));	 // 0.005 wins
	EXPECT_EQ(pairs[1], std::make_pair(size_t(2), size_t(3)));
}

TEST(TrajectoryEvaluator, TooFewAssociationsIsAClearError)
{
	const Trajectory gt = loop(10, 0);
	const Trajectory est = loop(10, 1000);
	try
	{
		TrajectoryEvaluator(0.02).evaluate(gt, est);
		FAIL();
	}
	catch (const InputError& e)
	{
		EXPECT_NE(std::string(e.what()).find("same time base"), std::string::npos);
	}
}

TEST(TrajectoryEvaluator, KummerleRelations)
{
	const Trajectory gt = loop(100);
	Trajectory est = gt;
	// Corrupt one pose: relations touching it see the error.
	est.poses[50].pose.x += 0.3;
	std::vector<PoseRelation> rels;
	for (size_t i = 0; i + 10 < gt.poses.size(); i += 10)
	{
		PoseRelation r;
		r.t1 = gt.poses[i].t;
		r.t2 = gt.poses[i + 10].t;
		r.delta = (CPose2D(gt.poses[i + 10].pose) - CPose2D(gt.poses[i].pose)).asTPose();
		rels.push_back(r);
	}
	PoseRelation unmatched;
	unmatched.t1 = 1e6;
	unmatched.t2 = 1e6 + 1;
	rels.push_back(unmatched);
	const EvaluationReport r = TrajectoryEvaluator(0.02).evaluateRelations(rels, est);
	EXPECT_EQ(r.relations, 10u);
	EXPECT_EQ(r.relationsMatched, 9u);
	EXPECT_NEAR(r.relationTranslation.max, 0.3, 1e-9);
	// Two relations (40->50 and 50->60) carry the 0.3 m error.
	EXPECT_NEAR(r.relationTranslation.mean, 2 * 0.3 / 9, 1e-9);
}

TEST(TrajectoryFile, DetectsAndReadsEveryFormat)
{
	TempDir dir;
	std::ofstream(dir.file("a.tum"))
		<< "# comment\n1.0 1 2 0 0 0 0.7071067811865476 0.7071067811865476\n"
		   "2.0 3 4 0 0 0 0 1\n";
	std::ofstream(dir.file("b.txt")) << "1.0 1 2 1.5\n2.0, 3, 4, -1.5\n";
	std::ofstream(dir.file("c.txt"))
		<< "1.0 1 2 0.5 0.01 0 0 0.02 0 0.003\n";
	std::ofstream(dir.file("d.rel")) << "1.0 2.0 0.5 0.1 0 0 0 0.2\n";
	using F = TrajectoryFile::Format;
	EXPECT_EQ(TrajectoryFile::detect(dir.file("a.tum")), F::Tum);
	EXPECT_EQ(TrajectoryFile::detect(dir.file("b.txt")), F::TimeXYYaw);
	EXPECT_EQ(TrajectoryFile::detect(dir.file("c.txt")), F::PosesCov);
	EXPECT_EQ(TrajectoryFile::detect(dir.file("d.rel")), F::Relations);

	const Trajectory a = TrajectoryFile::read(dir.file("a.tum"));
	ASSERT_EQ(a.poses.size(), 2u);
	EXPECT_NEAR(a.poses[0].pose.phi, M_PI / 2, 1e-12);
	EXPECT_NEAR(a.poses[1].pose.x, 3, 1e-12);
	const Trajectory c = TrajectoryFile::read(dir.file("c.txt"));
	ASSERT_TRUE(c.poses[0].hasCovariance);
	EXPECT_DOUBLE_EQ(c.poses[0].cov(1, 1), 0.02);
	const auto rel = TrajectoryFile::readRelations(dir.file("d.rel"));
	ASSERT_EQ(rel.size(), 1u);
	EXPECT_NEAR(rel[0].delta.phi, 0.2, 1e-12);
}

TEST(TrajectoryFile, BadRowsNameFileAndLine)
{
	TempDir dir;
	std::ofstream(dir.file("bad.txt")) << "1 0 0 0\n2 0 x 0\n";
	std::ofstream(dir.file("short.txt")) << "1 0 0 0\n2 0 0\n";
	std::ofstream(dir.file("back.txt")) << "2 0 0 0\n1 0 0 0\n";
	for (const auto& [file, expected] :
		 std::vector<std::pair<std::string, std::string>>{
			 {"bad.txt", "bad.txt:2: 'x'"},
			 {"short.txt", "short.txt:2: expected 4 columns"},
			 {"back.txt", "back.txt:2: time"}})
	{
		try
		{
			TrajectoryFile::read(dir.file(file));
			ADD_FAILURE() << file;
		}
		catch (const InputError& e)
		{
			EXPECT_NE(std::string(e.what()).find(expected), std::string::npos)
				<< e.what();
		}
	}
}
