// Moon, Miura & Shirai's segment stage (2.1-2.2) on real images, where no
// map is at hand: the vertical segments of the RTAB-Map hall pairs (door
// frames), and the vertical lines of the EuRoC pairs triangulated from two
// Vicon-measured poses of the same place, compared within their sigma.
// Prints Markdown (scripts/bench-stereo-real.sh puts it in
// doc/benchmarks.md) and writes the pictures into OUTDIR.
// Usage: featloc_bench_stereo_real EUROC_RECTIFIED.rawlog EUROC_BODY_GT.tum
//                                  RTABMAP.rawlog OUTDIR
#include <opencv2/calib3d.hpp>
#include <opencv2/core/utility.hpp>
#include <opencv2/features2d.hpp>
#include <opencv2/imgcodecs.hpp>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "featloc/eval/LineAgreement.h"
#include "featloc/io/DecodedStereoPair.h"
#include "featloc/io/TumPoseFile.h"
#include "featloc/output/StereoPairPicture.h"
#include "featloc/pipeline/StereoPairReader.h"
#include "featloc/registerClasses.h"
#include "featloc/stereo/StereoVerticalLines.h"

using namespace featloc;

namespace
{
struct Seen
{
	double t = 0;
	std::string where;
	mrpt::img::TStereoCamera calibration;
	mrpt::poses::CPose3D camera;  //!< left camera in the world
	StereoVerticalLines::Result result;
	cv::Mat left, right;
};

/** Every pair of the rawlog, its lines placed by `poseAt(t)`. */
template <typename PoseAt>
std::vector<Seen> look(const std::string& rawlog, const StereoVerticalLines& x, PoseAt poseAt)
{
	std::vector<Seen> out;
	StereoPairReader reader(rawlog);
	StereoPairReader::Pair p;
	while (reader.next(p))
	{
		const double t = mrpt::Clock::toDouble(p.observation->timestamp);
		const mrpt::poses::CPose3D cam = poseAt(t) + mrpt::poses::CPose3D(p.observation->cameraPose);
		Seen s;
		s.t = t;
		s.where = "'" + rawlog + "' entry " + std::to_string(p.entry);
		s.calibration = p.observation->getStereoCameraParams();
		s.camera = cam;
		s.left = p.images->left;
		s.right = p.images->right;
		s.result = x.extract(s.left, s.right, s.calibration, cam, s.where);
		out.push_back(std::move(s));
	}
	return out;
}

/** Pose of camera b in camera a's frame from the two left images alone:
 * ORB matches (cross-checked), OpenCV's essential matrix (RANSAC, 1 px) and
 * recoverPose give the rotation and the direction of travel; the length of
 * travel is `scale`. */
mrpt::poses::CPose3D relativePoseFromImages(const Seen& a, const Seen& b, double scale, int& inliers)
{
	auto orb = cv::ORB::create(2000);
	std::vector<cv::KeyPoint> ka, kb;
	cv::Mat da, db;
	orb->detectAndCompute(a.left, cv::noArray(), ka, da);
	orb->detectAndCompute(b.left, cv::noArray(), kb, db);
	cv::BFMatcher bf(cv::NORM_HAMMING, true);
	std::vector<cv::DMatch> m;
	bf.match(da, db, m);
	std::vector<cv::Point2f> pa, pb;
	for (const auto& x : m)
		if (x.distance < 50)
		{
			pa.push_back(ka[static_cast<size_t>(x.queryIdx)].pt);
			pb.push_back(kb[static_cast<size_t>(x.trainIdx)].pt);
		}
	inliers = 0;
	if (pa.size() < 8) return {};
	const auto& c = a.calibration.leftCamera;
	const cv::Mat K = (cv::Mat_<double>(3, 3) << c.fx(), 0, c.cx(), 0, c.fy(), c.cy(), 0, 0, 1);
	cv::Mat mask, R, t;
	const cv::Mat E = cv::findEssentialMat(pa, pb, K, cv::RANSAC, 0.999, 1.0, mask);
	if (E.rows != 3 || E.cols != 3) return {};
	inliers = cv::recoverPose(E, pa, pb, K, R, t, mask);
	// x_b = R x_a + t: camera b sits at -R^T t in a's frame, turned by R^T.
	mrpt::math::CMatrixDouble33 Rt;
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 3; j++) Rt(i, j) = R.at<double>(j, i);
	const cv::Mat c_b = -R.t() * t;
	mrpt::poses::CPose3D rel;
	rel.setRotationMatrix(Rt);
	const double n = cv::norm(c_b);
	rel.x(scale * c_b.at<double>(0) / n);
	rel.y(scale * c_b.at<double>(1) / n);
	rel.z(scale * c_b.at<double>(2) / n);
	return rel;
}

struct AgreementRow
{
	size_t pairs = 0, within = 0;
	double medianDistance = 0, medianSigma = 0;
};

AgreementRow agreement(const std::vector<WorldVerticalLine>& la, const std::vector<WorldVerticalLine>& lb)
{
	AgreementRow row;
	std::vector<double> dist, sig;
	for (const auto& p : LineAgreement::pair(la, lb))
	{
		row.pairs++;
		row.within += p.mahalanobis2 < 11.83;  // chi2, 2 dof, 99.73 % (3 sigma)
		dist.push_back(p.difference.norm());
		sig.push_back(std::sqrt((la[p.a].cov + lb[p.b].cov).trace()));
	}
	std::sort(dist.begin(), dist.end());
	std::sort(sig.begin(), sig.end());
	if (!dist.empty())
	{
		row.medianDistance = dist[dist.size() / 2];
		row.medianSigma = sig[sig.size() / 2];
	}
	return row;
}

double angleDeg(const mrpt::poses::CPose3D& p)
{
	const Eigen::Matrix3d R = p.getRotationMatrix().asEigen();
	return std::acos(std::max(-1.0, std::min(1.0, (R.trace() - 1) / 2))) * 180 / M_PI;
}

size_t supported(const StereoVerticalLines::Result& r)
{
	return static_cast<size_t>(std::count(r.matchRejection.begin(), r.matchRejection.end(), std::string()));
}
}  // namespace

int main(int argc, char** argv)
{
	if (argc < 5)
	{
		std::fprintf(stderr, "usage: %s EUROC_RECTIFIED.rawlog EUROC_BODY_GT.tum RTABMAP.rawlog OUTDIR\n", argv[0]);
		return 2;
	}
	featloc::registerClasses();
	cv::setNumThreads(1);
	const std::string euroc = argv[1], gtPath = argv[2], rtabmap = argv[3], outDir = argv[4];

	// The same options for both data sets, fixed before either was looked
	// at through this program: the extractor's defaults (the simulated
	// scenes'), the paper's 0.5 px image sigma, and the camera pose sigma
	// the data's README states (Vicon about 1 mm, camera-body calibration
	// about 1 cm; 0.1 deg of rotation assumed for the latter).
	StereoVerticalLines::Options o;
	o.sigma_position = 0.01;
	o.sigma_rotation_deg = 0.1;
	o.max_depth = 30;  // the hall is about 15 m deep
	const StereoVerticalLines x(o);

	// RTAB-Map hall: no ground truth; the robot at the origin (the importer
	// puts the camera level, looking along x).
	const auto hall = look(rtabmap, x, [](double) { return mrpt::poses::CPose3D(); });
	std::printf("#### RTAB-Map hall (rectified 640x480, fx 487.6 px, baseline 0.120 m)\n\n");
	std::printf("| pair | segments left / right | DP matches | supported by the SAD disparity | vertical lines 0.3-30 m |\n|---|---|---|---|---|\n");
	for (size_t i = 0; i < hall.size(); i++)
	{
		const auto& r = hall[i].result;
		std::printf("| %zu | %zu / %zu | %zu | %zu | %zu |\n", i, r.left.size(), r.right.size(), r.matches.size(),
			supported(r), r.lines.size());
		cv::imwrite(outDir + "/rtabmap-pair" + std::to_string(i) + ".png",
			StereoPairPicture::draw(hall[i].left, hall[i].right, r));
	}

	// EuRoC: Vicon body poses; pairs 0/1 and 2/3 of the data's README see one place each.
	const auto gt = TumPoseFile::read(gtPath);
	const auto eu = look(euroc, x, [&](double t) {
		const auto* row = TumPoseFile::nearest(gt, t, 0.005);
		if (!row) throw std::runtime_error("no ground-truth row near t = " + std::to_string(t));
		return row->pose;
	});
	// README numbering by time.
	const std::map<std::string, int> readmeIndex = {{"1403715386.76", 0}, {"1403715288.31", 1}, {"1403715400.76", 2}, {"1403715400.26", 3}};
	std::vector<const Seen*> byReadme(4, nullptr);
	for (const auto& s : eu)
	{
		char key[32];
		std::snprintf(key, sizeof(key), "%.2f", s.t);
		if (auto it = readmeIndex.find(key); it != readmeIndex.end()) byReadme[static_cast<size_t>(it->second)] = &s;
	}
	std::printf("\n#### EuRoC V1_01 pairs (rectified, Vicon poses)\n\n");
	std::printf("| pair | segments left / right | DP matches | supported | vertical lines |\n|---|---|---|---|---|\n");
	for (size_t i = 0; i < 4; i++)
	{
		if (!byReadme[i]) continue;
		const auto& r = byReadme[i]->result;
		std::printf("| %zu | %zu / %zu | %zu | %zu | %zu |\n", i, r.left.size(), r.right.size(), r.matches.size(),
			supported(r), r.lines.size());
		cv::imwrite(outDir + "/euroc-pair" + std::to_string(i) + ".png",
			StereoPairPicture::draw(byReadme[i]->left, byReadme[i]->right, r));
	}
	std::printf(
		"\n| pairs | relative pose of the second camera | its turn | lines paired | within 3 sigma | median "
		"distance | median sigma (sqrt trace) |\n|---|---|---|---|---|---|---|\n");
	for (const auto& [a, b] : {std::pair<size_t, size_t>{0, 1}, {2, 3}})
	{
		if (!byReadme[a] || !byReadme[b]) continue;
		const Seen &A = *byReadme[a], &B = *byReadme[b];
		const mrpt::poses::CPose3D vicon = B.camera - A.camera;
		int inliers = 0;
		const double travel = std::sqrt(vicon.x() * vicon.x() + vicon.y() * vicon.y() + vicon.z() * vicon.z());
		const mrpt::poses::CPose3D fromImages = relativePoseFromImages(A, B, travel, inliers);
		const auto rowVicon = agreement(A.result.lines, B.result.lines);
		const auto linesE = x.place(B.result, B.calibration, A.camera + fromImages, B.where);
		const auto rowImages = agreement(A.result.lines, linesE);
		auto print = [&](const char* what, double turn, const AgreementRow& r)
		{
			std::printf("| %zu / %zu | %s | %.2f deg | %zu | %zu (%.0f%%) | %.3f m | %.3f m |\n", a, b, what, turn, r.pairs,
				r.within, r.pairs ? 100.0 * static_cast<double>(r.within) / static_cast<double>(r.pairs) : 0.0,
				r.medianDistance, r.medianSigma);
		};
		print("Vicon (README)", angleDeg(vicon), rowVicon);
		char what[160];
		std::snprintf(what, sizeof(what),
			"left images' essential matrix (%d ORB inliers), Vicon's length of travel; %.2f deg from Vicon's turn",
			inliers, angleDeg(vicon - fromImages));
		print(what, angleDeg(fromImages), rowImages);
	}
	return 0;
}
