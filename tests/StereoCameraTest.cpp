// featloc-sim's stereo camera: exact geometry (OpenCV's block matcher
// against the exact disparity; ground-truth edges against the rendered
// intensity edges), same seed same bytes, worlds without a camera
// unchanged, and the reader's checks of stereo observations.
#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/obs/CObservationStereoImages.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/serialization/CArchive.h>
#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <opencv2/calib3d.hpp>
#include <opencv2/features2d.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "featloc/pipeline/StereoPairReader.h"
#include "featloc/registerClasses.h"
#include "featloc/sim/SimConfiguration.h"
#include "featloc/sim/Simulator.h"
#include "featloc/sim/StereoRenderer.h"
#include "featloc/sim/VisibleEdges.h"
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
const std::string kRun = FEATLOC_RUN_EXE;
const std::string kSim = FEATLOC_SIM_EXE;

std::string readFile(const std::string& path)
{
	std::ifstream f(path, std::ios::binary);
	std::stringstream ss;
	ss << f.rdbuf();
	return ss.str();
}

/** The paper's lab scene, with changes. */
SimConfiguration moonLab(const std::vector<std::array<std::string, 3>>& set = {})
{
	mrpt::config::CConfigFileMemory cfg(readFile(kSource + "/worlds/moon-lab.ini"));
	for (const auto& [section, key, value] : set) cfg.write(section, key, value);
	return SimConfiguration::load(cfg);
}

/** Floor or ceiling pixel of a level camera at height camZ. */
bool onFloorOrCeiling(double depth, int v, const StereoCameraOptions& c)
{
	const double z = c.pose[2] - depth * (v - c.cy) / c.fy;
	return std::abs(z) < 0.01 || std::abs(z - c.ceiling_height) < 0.01;
}
}  // namespace

TEST(StereoCamera, BlockMatcherAgreesWithTheExactDisparityOnTexturedWalls)
{
	const auto sc = moonLab();
	const StereoRenderer r(sc.world, sc.stereo);
	cv::RNG rng(7);
	for (const double y : {0.0, 1.0, 2.0})	// the paper's Figs. 5, 8 and 9
	{
		const auto f = r.render(mrpt::poses::CPose2D(0, y, M_PI / 2), 0, rng);
		// The papers' area-based matcher: 15x15 SAD with the left-right check.
		auto bm = cv::StereoBM::create(64, 15);
		bm->setDisp12MaxDiff(1);
		cv::Mat disp16;
		bm->compute(f.left, f.right, disp16);
		// Textured wall pixels: not floor or ceiling, some texture around
		// them, away from depth discontinuities (the window straddles them).
		cv::Mat mean, sq, leftF;
		f.left.convertTo(leftF, CV_32F);
		cv::blur(leftF, mean, cv::Size(15, 15));
		cv::blur(leftF.mul(leftF), sq, cv::Size(15, 15));
		// Depth jumps: no disparity (mixed pixels), or a step of more than
		// half a pixel of disparity to a neighbour, horizontally or
		// vertically.
		cv::Mat invalid = (f.disparity <= 0);
		for (int v = 0; v + 1 < f.disparity.rows; v++)
			for (int u = 0; u + 1 < f.disparity.cols; u++)
			{
				const float d0 = f.disparity.at<float>(v, u);
				if (std::abs(f.disparity.at<float>(v, u + 1) - d0) > 0.5f ||
					std::abs(f.disparity.at<float>(v + 1, u) - d0) > 0.5f)
					invalid.at<uchar>(v, u) = 255;
			}
		cv::dilate(invalid, invalid, cv::getStructuringElement(cv::MORPH_RECT, cv::Size(17, 17)));
		double sum2 = 0;
		size_t n = 0, matched = 0, gross = 0;
		for (int v = 8; v < f.left.rows - 8; v++)
			for (int u = 72; u < f.left.cols - 8; u++)
			{
				const float gt = f.disparity.at<float>(v, u);
				if (invalid.at<uchar>(v, u) || onFloorOrCeiling(f.depth.at<float>(v, u), v, sc.stereo))
					continue;
				const float m = mean.at<float>(v, u);
				if (std::sqrt(std::max(0.0f, sq.at<float>(v, u) - m * m)) < 8) continue;
				n++;
				const short d = disp16.at<short>(v, u);
				if (d <= 0) continue;
				matched++;
				const double e = d / 16.0 - gt;
				// A gross mismatch (more than 2 px off: the matcher chose
				// another window, KITTI counts these as "bad pixels") says
				// nothing about the geometry's accuracy; counted apart.
				if (std::abs(e) > 2)
				{
					gross++;
					continue;
				}
				sum2 += e * e;

			}
		ASSERT_GT(n, 20000u) << "too few textured wall pixels at y = " << y;
		const double rms = std::sqrt(sum2 / static_cast<double>(matched - gross));
		EXPECT_LT(static_cast<double>(gross), 0.001 * static_cast<double>(matched))
			<< gross << " gross mismatches at y = " << y;
		EXPECT_LE(rms, 0.3) << "StereoBM vs exact disparity at y = " << y << " m, " << matched
							<< " of " << n << " pixels matched";
		EXPECT_GT(static_cast<double>(matched), 0.8 * static_cast<double>(n));
		std::printf(
			"[          ] y = %.0f m: StereoBM RMS %.3f px over %zu of %zu textured wall pixels "
			"(%zu off by more than 2 px)\n",
			y, rms, matched, n, gross);
	}
}

TEST(StereoCamera, GroundTruthEdgesLandOnTheRenderedIntensityEdges)
{
	const auto sc = moonLab();
	const StereoRenderer r(sc.world, sc.stereo);
	const VisibleEdges edges(sc.world, sc.stereo);
	size_t checked = 0;
	double worst = 0;
	for (const double y : {0.0, 1.0, 2.0})
	{
		const auto cam = r.leftCameraPose(mrpt::poses::CPose2D(0.05, y, M_PI / 2 + 0.1));
		cv::Mat left, right, dl, dr;
		r.renderIdeal(cam, 0, left, right, dl, dr);	 // no noise: the edge itself
		for (const auto& e : edges.visible(cam, dl, dr))
		{
			const double uGt = 0.5 * (e.uLeftLow + e.uLeftHigh);
			const int u0 = static_cast<int>(std::floor(uGt));
			if (u0 < 3 || u0 + 4 >= left.cols) continue;
			// The intensity profile across the edge, averaged over the
			// middle of its visible rows (texture averages out, the edge
			// does not); its steepest step, refined by a parabola, is where
			// the intensity edge is.
			const int vTop = static_cast<int>(std::ceil(std::min(e.vLeftHigh, e.vLeftLow)));
			const int vBottom = static_cast<int>(std::floor(std::max(e.vLeftHigh, e.vLeftLow)));
			const int margin = (vBottom - vTop) / 5;
			if (vBottom - vTop < 10) continue;
			std::vector<float> row(static_cast<size_t>(left.cols), 0.0f);
			for (int v = vTop + margin; v <= vBottom - margin; v++)
				for (int u = u0 - 4; u <= u0 + 5; u++)
					row[static_cast<size_t>(u)] += left.at<float>(v, u) / static_cast<float>(vBottom - vTop - 2 * margin + 1);
			int best = -1;
			double bestG = 0;
			for (int u = u0 - 2; u <= u0 + 2; u++)
			{
				const double g = std::abs(row[static_cast<size_t>(u + 1)] - row[static_cast<size_t>(u)]);
				if (g > bestG) bestG = g, best = u;
			}
			if (bestG < 10) continue;  // a low-contrast edge (paint on paint)
			const auto at = [&](int u) { return row[static_cast<size_t>(u)]; };
			const double gm = std::abs(at(best) - at(best - 1));
			const double gp = std::abs(at(best + 2) - at(best + 1));
			const double den = gm - 2 * bestG + gp;
			const double offset = std::abs(den) > 1e-9 ? 0.5 * (gm - gp) / den : 0;
			// Pixel u covers [u - 0.5, u + 0.5]: the step between u and u+1
			// is at u + 0.5.
			const double uEdge = best + 0.5 + offset;
			EXPECT_NEAR(uEdge, uGt, 0.5) << e.edge.object << " s=" << e.edge.s << " at y=" << y;
			worst = std::max(worst, std::abs(uEdge - uGt));
			checked++;
		}
	}
	EXPECT_GE(checked, 20u);
	std::printf("[          ] %zu edges, worst |projected - rendered| %.3f px\n", checked, worst);
}

TEST(StereoCamera, SameSeedSameBytesImagesIncluded)
{
	registerClasses();
	TempDir a, b;
	for (const auto* d : {&a, &b})
	{
		const auto r = runCommand(
			shellQuote(kSim) + " " + shellQuote(kSource + "/worlds/moon-lab.ini") +
			" --set Simulation:duration=1.0 -q --out " + shellQuote(d->file("m")));
		ASSERT_EQ(r.exitCode, 0) << r.output;
	}
	size_t files = 0;
	for (const auto& entry : fs::recursive_directory_iterator(a.path()))
	{
		if (!entry.is_regular_file()) continue;
		const auto rel = fs::relative(entry.path(), a.path());
		if (rel.extension() == ".3Dscene") continue;  // MRPT scene: not ours to pin
		EXPECT_EQ(readFile(entry.path().string()), readFile((b.path() / rel).string()))
			<< rel << " differs between two runs with the same seed";
		files++;
	}
	// rawlog, gt, png, camera and edge gt, 3 pairs of images, 3 disparities
	EXPECT_GE(files, 14u);
	EXPECT_TRUE(fs::exists(a.path() / "m_Images" / "STEREO_000002_right.png"));
	// MRPT's own tool reads the log.
	const auto info = runCommand("rawlog-edit --info -i " + shellQuote(a.file("m.rawlog")));
	EXPECT_NE(info.output.find("STEREO"), std::string::npos) << info.output;
}

TEST(StereoCamera, WorldsWithoutACameraGiveTheSameBytesAsBefore)
{
	// The shipped rawlog was made before the stereo camera existed.
	TempDir d;
	const auto r = runCommand(
		shellQuote(kSim) + " " + shellQuote(kSource + "/worlds/corridor-people.ini") +
		" -q --out " + shellQuote(d.file("c")));
	ASSERT_EQ(r.exitCode, 0) << r.output;
	EXPECT_TRUE(
		readFile(d.file("c.rawlog")) ==
		readFile(kSource + "/rawlogs/sim/corridor-people.rawlog"));
	EXPECT_EQ(readFile(d.file("c.gt.txt")), readFile(kSource + "/rawlogs/sim/corridor-people.gt.txt"));
	EXPECT_FALSE(fs::exists(d.file("c_Images")));
}

TEST(StereoCamera, UnknownMaterialIsAnErrorNamingTheSection)
{
	EXPECT_THROW(
		{
			try
			{
				moonLab({{"Wall.partition", "texture", "velvet"}});
			}
			catch (const std::exception& e)
			{
				EXPECT_NE(std::string(e.what()).find("[Wall.partition] texture = velvet"), std::string::npos)
					<< e.what();
				throw;
			}
		},
		std::exception);
}

namespace
{
/** A simulated stereo log (laser off: stereo only) that featloc-run reads,
 * then broken in one way by `breakIt`; returns featloc-run's output. */
test::CommandResult runOnBrokenLog(
	const TempDir& d, const std::function<void(mrpt::obs::CObservationStereoImages&)>& breakObs,
	const std::function<void()>& breakFiles = {})
{
	registerClasses();
	auto sc = moonLab({{"Simulation", "duration", "0.4"}, {"Simulation", "format", "2"}});
	Simulator sim(sc.world, sc.robot, sc.laser, sc.odometry, sc.simulation, sc.beacons, sc.stereo);
	std::vector<mrpt::obs::CObservationStereoImages::Ptr> pairs;
	sim.onStereo([&](const SimulatedStereo& s) { pairs.push_back(s.observation); });
	sim.run(d.file("sim.rawlog"), d.file("sim.gt.txt"));
	// The same pairs, alone, in a new log beside the same images folder.
	fs::create_directory_symlink(d.path() / "sim_Images", d.path() / "stereo_Images");
	{
		mrpt::io::CFileGZOutputStream out(d.file("stereo.rawlog"));
		auto arch = mrpt::serialization::archiveFrom(out);
		for (size_t i = 0; i < pairs.size(); i++)
		{
			if (i == 1) breakObs(*pairs[i]);
			arch << *pairs[i];
		}
	}
	if (breakFiles) breakFiles();
	return runCommand(
		shellQuote(kRun) + " " + shellQuote(kSource + "/config.ini") + " -q --set Input:rawlog=" +
		shellQuote(d.file("stereo.rawlog")) + " --set Evaluation:ground_truth= --set " +
		"Pipeline:estimator=odometry --out " + shellQuote(d.file("out")));
}
}  // namespace

TEST(StereoCamera, RunReadsAStereoLogWithExternalImages)
{
	TempDir d;
	const auto r = runOnBrokenLog(d, [](mrpt::obs::CObservationStereoImages&) {});
	EXPECT_EQ(r.exitCode, 0) << r.output;
	const std::string summary = readFile(d.file("out/summary.json"));
	EXPECT_NE(summary.find("\"steps\": 2"), std::string::npos) << summary;
	EXPECT_NE(summary.find("\"stereo_pairs\": 2"), std::string::npos) << summary;
}

TEST(StereoCamera, MissingImageFileIsAnInputErrorNamingTheEntry)
{
	TempDir d;
	const auto r = runOnBrokenLog(
		d, [](mrpt::obs::CObservationStereoImages&) {},
		[&] { fs::remove(d.path() / "sim_Images" / "STEREO_000001_right.png"); });
	EXPECT_NE(r.exitCode, 0);
	EXPECT_NE(r.output.find("entry #1 (stereo 'STEREO'): the right image file"), std::string::npos)
		<< r.output;
	EXPECT_NE(r.output.find("STEREO_000001_right.png' is missing"), std::string::npos) << r.output;
}

TEST(StereoCamera, ImageThatDoesNotDecodeIsAnInputError)
{
	TempDir d;
	const auto r = runOnBrokenLog(
		d, [](mrpt::obs::CObservationStereoImages&) {},
		[&] { std::ofstream(d.path() / "sim_Images" / "STEREO_000001_left.png") << "not a png"; });
	EXPECT_NE(r.exitCode, 0);
	EXPECT_NE(r.output.find("entry #1 (stereo 'STEREO'): the left image file"), std::string::npos)
		<< r.output;
	EXPECT_NE(r.output.find("does not decode as an image"), std::string::npos) << r.output;
}

TEST(StereoCamera, LeftAndRightOfDifferentSizesIsAnInputError)
{
	TempDir d;
	const auto r = runOnBrokenLog(
		d, [](mrpt::obs::CObservationStereoImages&) {},
		[&] {
			const auto p = (d.path() / "sim_Images" / "STEREO_000001_right.png").string();
			cv::Mat m = cv::imread(p, cv::IMREAD_GRAYSCALE);
			cv::resize(m, m, cv::Size(320, 240));
			cv::imwrite(p, m);
		});
	EXPECT_NE(r.exitCode, 0);
	EXPECT_NE(r.output.find("entry #1 (stereo 'STEREO'): left image 640x480 and right image 320x240 differ in size"),
		std::string::npos)
		<< r.output;
}

TEST(StereoCamera, StereoObservationWithoutCalibrationIsAnInputError)
{
	TempDir d;
	const auto r = runOnBrokenLog(d, [](mrpt::obs::CObservationStereoImages& o) {
		o.leftCamera.setIntrinsicParamsFromValues(0, 0, 0, 0);
	});
	EXPECT_NE(r.exitCode, 0);
	EXPECT_NE(r.output.find("entry #1 (stereo 'STEREO'): stereo observation without a calibration: leftCamera"),
		std::string::npos)
		<< r.output;
	TempDir d2;
	const auto r2 = runOnBrokenLog(d2, [](mrpt::obs::CObservationStereoImages& o) {
		o.rightCameraPose = mrpt::poses::CPose3DQuat();
	});
	EXPECT_NE(r2.output.find("rightCameraPose gives no baseline"), std::string::npos) << r2.output;
}

TEST(StereoCamera, ImagesOfAbsurdSizeAreRefusedBeforeTheyAreDecoded)
{
	// A calibration for absurd images is corrupt, whatever the files hold.
	TempDir d;
	const auto r = runOnBrokenLog(d, [](mrpt::obs::CObservationStereoImages& o) {
		o.leftCamera.ncols = 100000;
	});
	EXPECT_NE(r.exitCode, 0);
	EXPECT_NE(r.output.find("entry #1 (stereo 'STEREO'): the leftCamera calibration is for "
							"100000x480 images: corrupt"),
		std::string::npos)
		<< r.output;
	// An image file whose header claims 12000x12000 pixels (a valid PNG of
	// 144 megapixels, a few hundred kB on disk) where the calibration says
	// 640x480: the decoder is refused the memory before it fills it.
	TempDir d2;
	const auto r2 = runOnBrokenLog(
		d2, [](mrpt::obs::CObservationStereoImages&) {},
		[&] {
			cv::imwrite((d2.path() / "sim_Images" / "STEREO_000001_left.png").string(),
				cv::Mat(12000, 12000, CV_8UC1, cv::Scalar(0)));
		});
	EXPECT_NE(r2.exitCode, 0);
#ifndef FEATLOC_SANITIZED_BUILD
	EXPECT_NE(r2.output.find("the left image file"), std::string::npos) << r2.output;
	EXPECT_NE(r2.output.find("does not decode as an image within 68 MiB (the calibration is "
							 "for 640x480)"),
		std::string::npos)
		<< r2.output;
#else
	// No allocation ceiling under ASan: decoded, then refused for its size.
	EXPECT_NE(r2.output.find("left image 12000x12000 and right image 640x480 differ in size"),
		std::string::npos)
		<< r2.output;
#endif
}

namespace
{
/** The stereo observations of a rawlog, in file order, read as featloc-run reads them. */
std::vector<std::shared_ptr<mrpt::obs::CObservationStereoImages>> readStereoObservations(const std::string& path)
{
	std::vector<std::shared_ptr<mrpt::obs::CObservationStereoImages>> out;
	StereoPairReader reader(path);
	StereoPairReader::Pair p;
	while (reader.next(p)) out.push_back(p.observation);
	return out;
}

/** ORB matches between two images (cross-checked, Hamming distance below
 * 40): the pixel pairs. */
std::vector<std::pair<cv::Point2f, cv::Point2f>> orbMatches(const cv::Mat& a, const cv::Mat& b)
{
	auto orb = cv::ORB::create(1500);
	std::vector<cv::KeyPoint> ka, kb;
	cv::Mat da, db;
	orb->detectAndCompute(a, cv::noArray(), ka, da);
	orb->detectAndCompute(b, cv::noArray(), kb, db);
	cv::BFMatcher bf(cv::NORM_HAMMING, true);
	std::vector<cv::DMatch> m;
	bf.match(da, db, m);
	std::vector<std::pair<cv::Point2f, cv::Point2f>> pairs;
	for (const auto& x : m)
		if (x.distance < 40)
			pairs.emplace_back(ka[static_cast<size_t>(x.queryIdx)].pt, kb[static_cast<size_t>(x.trainIdx)].pt);
	return pairs;
}

double median(std::vector<double> v)
{
	if (v.empty()) return 1e9;
	std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
	return v[v.size() / 2];
}

/** Median |dy| of ORB matches between two images: 0 for a perfectly
 * rectified pair. */
double medianOrbDy(const cv::Mat& left, const cv::Mat& right, size_t& matches)
{
	std::vector<double> dy;
	for (const auto& [l, r] : orbMatches(left, right)) dy.push_back(std::abs(l.y - r.y));
	matches = dy.size();
	return median(dy);
}
}  // namespace

TEST(StereoImport, RealPairsBecomeRawlogsThatRunReads)
{
	const std::string import = FEATLOC_STEREO_IMPORT_EXE;
	const std::string data = kSource + "/../shared/data/stereo/";
	if (!fs::exists(data)) GTEST_SKIP() << "no " << data;
	TempDir d;
	for (const auto& [set, extra] : {std::pair<std::string, std::string>{"rtabmap-indoor-rect", ""},
			 {"euroc-v1-pairs", " --rectify"}, {"euroc-v1-pairs", ""}})
	{
		const std::string out = d.file(set + (extra.empty() ? "" : "-rect") + ".rawlog");
		const auto imp = runCommand(
			shellQuote(import) + " " + shellQuote(data + set) + extra + " --out " + shellQuote(out));
		ASSERT_EQ(imp.exitCode, 0) << imp.output;
		const auto run = runCommand(
			shellQuote(kRun) + " " + shellQuote(kSource + "/config.ini") + " -q --set Input:rawlog=" +
			shellQuote(out) + " --set Evaluation:ground_truth= --set Pipeline:estimator=odometry --out " +
			shellQuote(out + ".results"));
		EXPECT_EQ(run.exitCode, 0) << set << extra << ": " << run.output;
	}
	// After rectification, matches between left and right lie on the same
	// row; before it, EuRoC's lens and rotation put them rows apart.
	for (int i = 0; i < 4; i++)
	{
		char name[64];
		std::snprintf(name, sizeof(name), "STEREO_%06d_", i);
		size_t n = 0, nRaw = 0;
		const double dy = medianOrbDy(
			cv::imread(d.file("euroc-v1-pairs-rect_Images/") + name + "left.png", cv::IMREAD_GRAYSCALE),
			cv::imread(d.file("euroc-v1-pairs-rect_Images/") + name + "right.png", cv::IMREAD_GRAYSCALE), n);
		const double dyRaw = medianOrbDy(
			cv::imread(d.file("euroc-v1-pairs_Images/") + name + "left.png", cv::IMREAD_GRAYSCALE),
			cv::imread(d.file("euroc-v1-pairs_Images/") + name + "right.png", cv::IMREAD_GRAYSCALE), nRaw);
		EXPECT_GE(n, 50u) << "pair " << i;
		EXPECT_LE(dy, 0.5) << "pair " << i << ": median |dy| of " << n << " ORB matches";
		std::printf(
			"[          ] EuRoC pair %d: ORB median |dy| %.3f px rectified (%zu matches), %.3f px raw\n",
			i, dy, n, dyRaw);
	}
	// The rectified left camera is the raw one turned by the rectification
	// (cameraPose): the same scene point seen in the raw image (through its
	// lens) and in the rectified one gives the same ray on the body. ORB
	// matches between the raw and the rectified left images are such points.
	const auto raw = readStereoObservations(d.file("euroc-v1-pairs.rawlog"));
	const auto rect = readStereoObservations(d.file("euroc-v1-pairs-rect.rawlog"));
	ASSERT_EQ(raw.size(), 4u);
	ASSERT_EQ(rect.size(), 4u);
	for (size_t i = 0; i < 4; i++)
	{
		char name[64];
		std::snprintf(name, sizeof(name), "STEREO_%06zu_left.png", i);
		const auto pairs = orbMatches(
			cv::imread(d.file("euroc-v1-pairs_Images/") + name, cv::IMREAD_GRAYSCALE),
			cv::imread(d.file("euroc-v1-pairs-rect_Images/") + name, cv::IMREAD_GRAYSCALE));
		const auto& cr = raw[i]->leftCamera;
		const auto& cq = rect[i]->leftCamera;
		const cv::Matx33d K(cr.fx(), 0, cr.cx(), 0, cr.fy(), cr.cy(), 0, 0, 1);
		const std::vector<double> D{cr.dist[0], cr.dist[1], cr.dist[2], cr.dist[3], cr.dist[4]};
		std::vector<cv::Point2f> rawPx, undist;
		for (const auto& pr : pairs) rawPx.push_back(pr.first);
		cv::undistortPoints(rawPx, undist, K, D);
		const Eigen::Matrix3d Rraw = mrpt::poses::CPose3D(raw[i]->cameraPose).getRotationMatrix().asEigen();
		const Eigen::Matrix3d Rrect = mrpt::poses::CPose3D(rect[i]->cameraPose).getRotationMatrix().asEigen();
		// ORB places keypoints on pyramid levels, a pixel or more apart
		// between two images of different scale: single rays scatter. A
		// wrong camera pose is a rotation common to all of them, so what is
		// checked is the rotation that best aligns the two sets (Kabsch):
		// 0.6 deg, the rectification's own turn, before the importer put it
		// in cameraPose; 0.01-0.03 deg now.
		std::vector<double> angle;
		Eigen::Matrix3d H = Eigen::Matrix3d::Zero();
		for (size_t k = 0; k < pairs.size(); k++)
		{
			const Eigen::Vector3d a = Rraw * Eigen::Vector3d(undist[k].x, undist[k].y, 1).normalized();
			const Eigen::Vector3d b =
				Rrect * Eigen::Vector3d((pairs[k].second.x - cq.cx()) / cq.fx(),
							(pairs[k].second.y - cq.cy()) / cq.fy(), 1)
							.normalized();
			angle.push_back(std::acos(std::min(1.0, a.dot(b))) * 180 / M_PI);
			if (angle.back() < 1) H += b * a.transpose();  // gross ORB mismatches left out
		}
		Eigen::JacobiSVD<Eigen::Matrix3d> svd(H, Eigen::ComputeFullU | Eigen::ComputeFullV);
		Eigen::Matrix3d R = svd.matrixV() * svd.matrixU().transpose();
		if (R.determinant() < 0)
		{
			Eigen::Matrix3d V = svd.matrixV();
			V.col(2) *= -1;
			R = V * svd.matrixU().transpose();
		}
		const double offset = Eigen::AngleAxisd(R).angle() * 180 / M_PI;
		EXPECT_GE(angle.size(), 100u) << "pair " << i;
		EXPECT_LE(offset, 0.05) << "pair " << i << ": rotation between the raw and the rectified rays";
		std::printf(
			"[          ] EuRoC pair %zu: raw vs rectified left camera: rays %.3f deg apart (rotation that aligns "
			"them), single rays median %.3f deg (%zu ORB matches)\n",
			i, offset, median(angle), angle.size());
	}
}

TEST(StereoCamera, ShippedStereoRawlogIsReproducedByteForByte)
{
	TempDir d;
	const auto r = runCommand(
		shellQuote(kSim) + " " + shellQuote(kSource + "/worlds/moon-lab.ini") + " -q --out " +
		shellQuote(d.file("moon-lab")));
	ASSERT_EQ(r.exitCode, 0) << r.output;
	const std::string shipped = kSource + "/rawlogs/stereo/";
	for (const std::string f :
		 {"moon-lab.rawlog", "moon-lab.gt.txt", "moon-lab.camera.gt.txt", "moon-lab.edges.gt.txt",
			 "moon-lab_Images/STEREO_000015_left.png", "moon-lab_Images/STEREO_000015_right.png",
			 "moon-lab_GT/STEREO_000015_disparity.png"})
		EXPECT_TRUE(readFile(d.file(f)) == readFile(shipped + f)) << f << " differs from the shipped one";
}

TEST(StereoCamera, LensAndTiltWrittenToTheRawlogAreUndoneByItsCalibration)
{
	// A camera pitched 4 deg down and rolled 2 deg, behind a barrel lens
	// like EuRoC's. Undistorting the logged image with the calibration the
	// rawlog carries must give the image of an ideal pinhole camera in the
	// same pose: that is what the rectification downstream relies on.
	registerClasses();
	const std::string lens = "[-0.28 0.074 0.0002 0.00002 0]", pose = "[0 0 1.0 0 4 2]";
	TempDir d;
	const auto sim = runCommand(
		shellQuote(kSim) + " " + shellQuote(kSource + "/worlds/moon-lab.ini") +
		" --set Simulation:duration=0.1 --set StereoCamera:noise_sigma=0 --set StereoCamera:blur_sigma=0 "
		"--set StereoCamera:gain_change=0 --set 'StereoCamera:distortion=" + lens +
		"' --set 'StereoCamera:pose=" + pose + "' -q --out " + shellQuote(d.file("m")));
	ASSERT_EQ(sim.exitCode, 0) << sim.output;
	mrpt::obs::CObservationStereoImages::Ptr obs;
	{
		mrpt::io::CFileGZInputStream f(d.file("m.rawlog"));
		auto arch = mrpt::serialization::archiveFrom(f);
		while (!obs)
		{
			auto sf = arch.ReadObject();
			if (auto s = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(sf))
				obs = s->getObservationByClass<mrpt::obs::CObservationStereoImages>();
			else
				obs = std::dynamic_pointer_cast<mrpt::obs::CObservationStereoImages>(sf);
		}
	}
	const auto& cal = obs->leftCamera;
	ASSERT_NEAR(cal.dist[0], -0.28, 1e-12) << "the lens is not in the rawlog's calibration";
	const cv::Mat logged = cv::imread(d.file("m_Images/STEREO_000000_left.png"), cv::IMREAD_GRAYSCALE);
	ASSERT_FALSE(logged.empty());
	const cv::Matx33d K(cal.fx(), 0, cal.cx(), 0, cal.fy(), cal.cy(), 0, 0, 1);
	const cv::Mat dist = (cv::Mat_<double>(1, 5) << cal.dist[0], cal.dist[1], cal.dist[2], cal.dist[3], cal.dist[4]);
	cv::Mat undistorted;
	cv::undistort(logged, undistorted, K, dist);

	// The ideal pinhole camera in the same pose, at the frame's pose.
	const auto ideal = moonLab({{"StereoCamera", "pose", pose}});
	const StereoRenderer r(ideal.world, ideal.stereo);
	cv::Mat left, right, dl, dr, left8;
	r.renderIdeal(r.leftCameraPose(mrpt::poses::CPose2D(0, 0, M_PI / 2)), 0, left, right, dl, dr);
	left.convertTo(left8, CV_8U);
	const auto meanAbsDiff = [&](const cv::Mat& a) {
		// Away from the border (undistort leaves it black), at the scale of
		// the scene (two resamplings blur texture that one does not).
		const cv::Rect inner(40, 40, left8.cols - 80, left8.rows - 80);
		cv::Mat ga, gb, diff;
		cv::GaussianBlur(a(inner), ga, cv::Size(0, 0), 1.5);
		cv::GaussianBlur(left8(inner), gb, cv::Size(0, 0), 1.5);
		cv::absdiff(ga, gb, diff);
		return cv::mean(diff)[0];
	};
	const double undone = meanAbsDiff(undistorted), notUndone = meanAbsDiff(logged);
	EXPECT_LT(undone, 1.5) << "mean |undistorted - ideal| in grey levels";
	EXPECT_GT(notUndone, 4 * undone) << "the lens should show before undistortion";
	// The tilt is in the image too: a level camera sees something else.
	const auto level = moonLab();
	const StereoRenderer rl(level.world, level.stereo);
	cv::Mat levelLeft, levelLeft8;
	rl.renderIdeal(rl.leftCameraPose(mrpt::poses::CPose2D(0, 0, M_PI / 2)), 0, levelLeft, right, dl, dr);
	levelLeft.convertTo(levelLeft8, CV_8U);
	EXPECT_GT(meanAbsDiff(levelLeft8), 4 * undone) << "the pitch and roll should show";
	std::printf(
		"[          ] mean |image - ideal pinhole|: %.2f grey levels undistorted with the logged "
		"calibration, %.2f as logged\n",
		undone, notUndone);
}
