// The segment stage of Moon, Miura & Shirai (2.1-2.2) on real images and
// the 3-D pieces that place its lines without a map: the triangulation of
// a segment match, and the pairing of lines seen from two poses.
#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include <Eigen/Dense>
#include <cmath>
#include <filesystem>

#include "featloc/core/InputError.h"
#include "featloc/eval/LineAgreement.h"
#include "featloc/io/DecodedStereoPair.h"
#include "featloc/pipeline/StereoPairReader.h"
#include "featloc/registerClasses.h"
#include "featloc/stereo/SegmentTriangulator.h"
#include "featloc/stereo/StereoVerticalLines.h"
#include "support/CommandRunner.h"
#include "support/TempDir.h"

using namespace featloc;
using featloc::test::runCommand;
using featloc::test::shellQuote;
using featloc::test::TempDir;
namespace fs = std::filesystem;

namespace
{
const std::string kSource = FEATLOC_SOURCE_DIR;
const std::string kImport = FEATLOC_STEREO_IMPORT_EXE;

SegmentTriangulator camera()
{
	SegmentTriangulator t;
	t.fx = 480;
	t.fy = 470;
	t.cx = 320;
	t.cy = 240;
	t.baseline = 0.12;
	return t;
}
}  // namespace

TEST(SegmentTriangulator, PointProjectsBackAndItsJacobianIsTheFiniteDifference)
{
	const auto t = camera();
	const Eigen::Vector3d p(0.7, -0.4, 3.5);  // x right, y down, z ahead
	const double ul = t.cx + t.fx * p.x() / p.z(), ur = t.cx + t.fx * (p.x() - t.baseline) / p.z(),
				 v = t.cy + t.fy * p.y() / p.z();
	Eigen::Matrix3d J;
	EXPECT_LT((t.point(ul, ur, v, &J) - p).norm(), 1e-12);
	const double h = 1e-6;
	for (int k = 0; k < 3; k++)
	{
		double a[3] = {ul, ur, v}, b[3] = {ul, ur, v};
		a[k] += h;
		b[k] -= h;
		const Eigen::Vector3d num = (t.point(a[0], a[1], a[2]) - t.point(b[0], b[1], b[2])) / (2 * h);
		EXPECT_LT((num - J.col(k)).norm(), 1e-6) << "column " << k;
	}
}

TEST(SegmentTriangulator, SegmentEndsAreTheMatchCommonRows)
{
	const auto t = camera();
	VerticalSegment l, r;
	l.u = 400;
	r.u = 380;	// 20 px disparity: z = 480 * 0.12 / 20 = 2.88 m
	l.vTop = r.vTop = 100;
	l.vBottom = r.vBottom = 300;
	SegmentMatch m;
	m.vLow = 120;
	m.vHigh = 280;
	const auto s = t.triangulate(l, r, m);
	EXPECT_NEAR(s.top.z(), 2.88, 1e-9);
	EXPECT_NEAR(s.bottom.z(), 2.88, 1e-9);
	EXPECT_NEAR(s.top.y(), (120 - 240) * 2.88 / 470, 1e-9);
	EXPECT_NEAR(s.bottom.y(), (280 - 240) * 2.88 / 470, 1e-9);
	// Depth sigma: z^2 / (f B) * sqrt(2) * 0.5 px.
	EXPECT_NEAR(std::sqrt(s.covMiddle(2, 2)), 2.88 * 2.88 / (480 * 0.12) * std::sqrt(2.0) * 0.5, 1e-9);
}

TEST(LineAgreement, MutualNearestLinesPairAndAWrongOneDisagreesInsteadOfVanishing)
{
	auto line = [](double x, double y, double s, int pol)
	{
		WorldVerticalLine w;
		w.xy = {x, y};
		w.cov = Eigen::Matrix2d::Identity() * s * s;
		w.zLow = 0.2;
		w.zHigh = 1.8;
		w.polarity = pol;
		return w;
	};
	const std::vector<WorldVerticalLine> a = {line(0, 3, 0.02, 1), line(1, 3, 0.02, -1), line(2, 3, 0.02, 1)};
	std::vector<WorldVerticalLine> b = {line(0.01, 3.02, 0.02, 1), line(1.3, 3, 0.02, -1), line(2, 3, 0.02, -1)};
	const auto pairs = LineAgreement::pair(a, b);
	ASSERT_EQ(pairs.size(), 2u);  // the third differs in polarity
	EXPECT_EQ(pairs[0].b, 0u);
	EXPECT_LT(pairs[0].mahalanobis2, 1.0);
	EXPECT_EQ(pairs[1].b, 1u);
	EXPECT_GT(pairs[1].mahalanobis2, 11.83);  // 0.3 m off: paired, and outside 3 sigma
	b[1].zLow = 2.0;
	b[1].zHigh = 3.0;  // no common heights: not the same line
	EXPECT_TRUE(LineAgreement::pair({a[1]}, {b[1]}).empty());
}

TEST(StereoRealPairs, HallDoorFramesAreFoundMatchedAndSupportedBySad)
{
	const std::string data = kSource + "/../shared/data/stereo/rtabmap-indoor-rect";
	if (!fs::exists(data)) GTEST_SKIP() << "no " << data;
	featloc::registerClasses();
	TempDir d;
	const auto imp = runCommand(shellQuote(kImport) + " " + shellQuote(data) + " --out " + shellQuote(d.file("hall.rawlog")));
	ASSERT_EQ(imp.exitCode, 0) << imp.output;
	StereoPairReader reader(d.file("hall.rawlog"));
	StereoPairReader::Pair p;
	ASSERT_TRUE(reader.next(p));
	StereoVerticalLines::Options o;
	o.max_depth = 30;
	const auto r = StereoVerticalLines(o).extract(
		p.images->left, p.images->right, p.observation->getStereoCameraParams(),
		mrpt::poses::CPose3D(p.observation->cameraPose), "hall");  // robot at the origin
	// Door-frame edges in the left image of pair 50, read by hand off its
	// intensity profile at row 220 (|dI/du| > 40): the left doorway's left
	// edge, the double door's left and right frame, the right doorway's
	// right edge.
	for (const double u : {70.0, 111.5, 218.5, 250.0})
	{
		bool found = false;
		for (size_t i = 0; i < r.matches.size() && !found; i++)
		{
			const auto& m = r.matches[i];
			const auto& s = r.left[m.left];
			found = r.matchRejection[i].empty() && m.vLow <= 220 && m.vHigh >= 220 && std::abs(s.uAt(220) - u) < 3;
		}
		EXPECT_TRUE(found) << "no supported match on the door-frame edge at u = " << u;
	}
	// Most DP matches are supported by the SAD disparity, and give lines.
	size_t supported = 0;
	for (const auto& why : r.matchRejection) supported += why.empty();
	EXPECT_GE(supported * 10, r.matches.size() * 8) << supported << " of " << r.matches.size();
	EXPECT_GE(r.lines.size(), 20u);
}

TEST(StereoVerticalLines, BlankOrTinyImagesGiveNoLinesAndAMissingCalibrationIsAnError)
{
	mrpt::img::TStereoCamera c;
	c.leftCamera.setIntrinsicParamsFromValues(480, 480, 32, 24);
	c.leftCamera.ncols = 64;
	c.leftCamera.nrows = 48;
	c.rightCamera = c.leftCamera;
	c.rightCameraPose = mrpt::math::TPose3DQuat(0.12, 0, 0, 1, 0, 0, 0);
	const StereoVerticalLines x;
	for (const cv::Mat& img : {cv::Mat(48, 64, CV_8U, cv::Scalar(128)), cv::Mat(20, 20, CV_8U, cv::Scalar(0))})
	{
		const auto r = x.extract(img, img, c, mrpt::poses::CPose3D(), "blank");
		EXPECT_TRUE(r.lines.empty());
	}
	cv::Mat l(48, 64, CV_8U, cv::Scalar(40));
	cv::line(l, {30, 0}, {30, 47}, cv::Scalar(220), 3);
	mrpt::img::TStereoCamera none;
	none.rightCameraPose = mrpt::math::TPose3DQuat(0, 0, 0, 1, 0, 0, 0);
	EXPECT_THROW(x.extract(l, l, none, mrpt::poses::CPose3D(), "no calibration"), InputError);
}
