#include "featloc/io/StereoCalibrationFile.h"

#include <mrpt/math/CMatrixFixed.h>
#include <mrpt/poses/CPose3DQuat.h>
#include <opencv2/core.hpp>

#include <cmath>

#include "featloc/core/InputError.h"

namespace featloc
{
namespace
{
/** Numbers of a node: a sequence, or an OpenCV/ROS matrix map {rows, cols,
 * data}. */
std::vector<double> numbers(const cv::FileNode& n)
{
	std::vector<double> out;
	const cv::FileNode seq = n.isMap() ? n["data"] : n;
	if (seq.isSeq())
		for (const auto& x : seq) out.push_back(static_cast<double>(x));
	return out;
}

std::vector<double> require(
	const cv::FileStorage& fs, const std::string& path, const char* key, size_t minCount)
{
	const cv::FileNode n = fs[key];
	if (n.empty())
		throw InputError("stereo calibration '" + path + "': no '" + std::string(key) + "'");
	auto v = numbers(n);
	if (v.size() < minCount)
		throw InputError(
			"stereo calibration '" + path + "': '" + std::string(key) + "' needs at least " +
			std::to_string(minCount) + " numbers, it has " + std::to_string(v.size()));
	for (double x : v)
		if (!std::isfinite(x))
			throw InputError(
				"stereo calibration '" + path + "': '" + std::string(key) + "' is not finite");
	return v;
}

cv::FileStorage open(const std::string& path)
{
	cv::FileStorage fs;
	try
	{
		fs.open(path, cv::FileStorage::READ);
	}
	catch (const cv::Exception& e)
	{
		throw InputError("stereo calibration '" + path + "' does not parse: " + e.msg);
	}
	if (!fs.isOpened()) throw InputError("stereo calibration '" + path + "' cannot be read");
	return fs;
}

struct OneCamera
{
	mrpt::img::TCamera camera;
	mrpt::poses::CPose3D bodyPose;	//!< euroc
	double projectionTx = 0;  //!< opencv: P(0,3)
	bool euroc = false;
};

OneCamera readCamera(const std::string& path, const std::string& name)
{
	cv::FileStorage fs = open(path);
	OneCamera c;
	c.camera.cameraName = name;
	c.euroc = !fs["T_BS"].empty();
	if (c.euroc)
	{
		const auto k = require(fs, path, "intrinsics", 4);
		const auto res = require(fs, path, "resolution", 2);
		const auto d = require(fs, path, "distortion_coefficients", 4);
		const auto T = require(fs, path, "T_BS", 16);
		c.camera.setIntrinsicParamsFromValues(k[0], k[1], k[2], k[3]);
		c.camera.ncols = static_cast<uint32_t>(res[0]);
		c.camera.nrows = static_cast<uint32_t>(res[1]);
		c.camera.setDistortionPlumbBob(d[0], d[1], d[2], d[3], d.size() > 4 ? d[4] : 0);
		mrpt::math::CMatrixDouble44 m;
		for (int i = 0; i < 16; i++) m(i / 4, i % 4) = T[static_cast<size_t>(i)];
		c.bodyPose = mrpt::poses::CPose3D(m);
	}
	else
	{
		const auto K = require(fs, path, "camera_matrix", 9);
		const auto d = require(fs, path, "distortion_coefficients", 4);
		int width = 0, height = 0;
		fs["image_width"] >> width;
		fs["image_height"] >> height;
		if (width <= 0 || height <= 0)
			throw InputError("stereo calibration '" + path + "': no image_width / image_height");
		c.camera.setIntrinsicParamsFromValues(K[0], K[4], K[2], K[5]);
		c.camera.ncols = static_cast<uint32_t>(width);
		c.camera.nrows = static_cast<uint32_t>(height);
		const bool none = d[0] == 0 && d[1] == 0 && d[2] == 0 && d[3] == 0 && (d.size() < 5 || d[4] == 0);
		if (none)
			c.camera.distortion = mrpt::img::DistortionModel::none;
		else
			c.camera.setDistortionPlumbBob(d[0], d[1], d[2], d[3], d.size() > 4 ? d[4] : 0);
		if (!fs["projection_matrix"].empty())
			c.projectionTx = require(fs, path, "projection_matrix", 12)[3];
	}
	if (!(c.camera.fx() > 0 && c.camera.fy() > 0))
		throw InputError("stereo calibration '" + path + "': focal lengths must be > 0");
	return c;
}
}  // namespace

StereoCalibrationFile StereoCalibrationFile::load(
	const std::string& leftPath, const std::string& rightPath)
{
	const OneCamera l = readCamera(leftPath, "LEFT"), r = readCamera(rightPath, "RIGHT");
	if (l.euroc != r.euroc)
		throw InputError(
			"stereo calibration: '" + leftPath + "' and '" + rightPath + "' are of different formats");
	StereoCalibrationFile out;
	out.stereo.leftCamera = l.camera;
	out.stereo.rightCamera = r.camera;
	if (l.euroc)
	{
		out.format = "euroc";
		out.hasBodyPose = true;
		out.leftCameraOnBody = l.bodyPose;
		// Right camera in the left camera's frame: T_BS_L^-1 * T_BS_R.
		const mrpt::poses::CPose3D rightInLeft = r.bodyPose - l.bodyPose;
		out.stereo.rightCameraPose = mrpt::poses::CPose3DQuat(rightInLeft).asTPose();
	}
	else
	{
		out.format = "opencv";
		// A rectified pair: the right projection matrix holds -fx * baseline.
		const double baseline = -r.projectionTx / r.camera.fx();
		if (!(baseline > 0))
			throw InputError(
				"stereo calibration '" + rightPath +
				"': projection_matrix gives no baseline (P(0,3) = -fx * baseline must be < 0)");
		out.stereo.rightCameraPose = mrpt::math::TPose3DQuat(baseline, 0, 0, 1, 0, 0, 0);
		// A forward-looking camera on the robot (x forward, z up).
		out.leftCameraOnBody =
			mrpt::poses::CPose3D(0, 0, 0, -M_PI / 2, 0, -M_PI / 2);
	}
	return out;
}
}  // namespace featloc
