#include "featloc/stereo/StereoVerticalLines.h"

#include <Eigen/Dense>
#include <cmath>

namespace featloc
{
namespace
{
Eigen::Matrix3d skew(const Eigen::Vector3d& v)
{
	Eigen::Matrix3d S;
	S << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
	return S;
}
}  // namespace

StereoVerticalLines::Result StereoVerticalLines::extract(
	const cv::Mat& left, const cv::Mat& right, const mrpt::img::TStereoCamera& calibration,
	const mrpt::poses::CPose3D& cameraInWorld, const std::string& where) const
{
	Result res;
	const VerticalSegmentDetector detector(options.segments);
	res.left = detector.detect(left);
	res.right = detector.detect(right);
	res.matches = SegmentStereoMatcher(options.matching).match(res.left, res.right);
	const SadDisparity sad(options.sad);
	res.disparity = sad.compute(left, right, 0, options.num_disparities);
	for (const auto& m : res.matches) res.matchRejection.push_back(sad.support(res.disparity, res.left[m.left], m));
	res.lines = place(res, calibration, cameraInWorld, where);
	return res;
}

std::vector<WorldVerticalLine> StereoVerticalLines::place(const Result& res,
	const mrpt::img::TStereoCamera& calibration, const mrpt::poses::CPose3D& cameraInWorld,
	const std::string& where) const
{
	SegmentTriangulator tri = SegmentTriangulator::fromCalibration(calibration, where);
	tri.sigmaColumn = options.sigma_img;
	std::vector<WorldVerticalLine> lines;
	const Eigen::Matrix3d R = cameraInWorld.getRotationMatrix().asEigen();
	const Eigen::Vector3d t(cameraInWorld.x(), cameraInWorld.y(), cameraInWorld.z());
	const double sp2 = options.sigma_position * options.sigma_position;
	const double sr = options.sigma_rotation_deg * M_PI / 180;
	for (size_t i = 0; i < res.matches.size(); i++)
	{
		const auto& m = res.matches[i];
		if (!res.matchRejection[i].empty()) continue;
		const TriangulatedSegment s = tri.triangulate(res.left[m.left], res.right[m.right], m);
		if (!(s.middle.z() >= options.min_depth && s.middle.z() <= options.max_depth)) continue;
		// Ends whose disparity is not positive (segments that cross within
		// the common rows) lie behind the camera or at infinity: no line.
		if (!(s.top.z() > 0 && s.bottom.z() > 0 && std::isfinite(s.top.z()) && std::isfinite(s.bottom.z()))) continue;
		const Eigen::Vector3d top = R * s.top + t, bottom = R * s.bottom + t;
		const Eigen::Vector3d dir = (top - bottom).normalized();
		WorldVerticalLine w;
		w.tiltDeg = std::acos(std::min(1.0, std::abs(dir.z()))) * 180 / M_PI;
		if (w.tiltDeg > options.max_tilt_deg) continue;
		// The middle point, turned into the world; the camera pose's
		// uncertainty: a turn dtheta moves it by -[R p]_x dtheta.
		const Eigen::Vector3d rp = R * s.middle;
		Eigen::Matrix3d cov = R * s.covMiddle * R.transpose() + sp2 * Eigen::Matrix3d::Identity() +
							  sr * sr * skew(rp) * skew(rp).transpose();
		w.xy = (rp + t).head<2>();
		w.cov = cov.topLeftCorner<2, 2>();
		w.zLow = std::min(top.z(), bottom.z());
		w.zHigh = std::max(top.z(), bottom.z());
		w.polarity = res.left[m.left].polarity;
		w.depth = s.middle.z();
		w.match = i;
		lines.push_back(w);
	}
	return lines;
}
}  // namespace featloc
