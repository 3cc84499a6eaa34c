#include "featloc/sim/StereoOutputWriter.h"

#include <mrpt/poses/CPose3DQuat.h>
#include <opencv2/imgcodecs.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

namespace featloc
{
namespace fs = std::filesystem;

StereoOutputWriter::StereoOutputWriter(
	const StereoCameraOptions& camera, const std::string& rawlogPath, const std::string& gtPrefix)
	: m_cam(camera)
{
	const fs::path raw(rawlogPath);
	m_imagesDir = (raw.parent_path() / (raw.stem().string() + "_Images")).string();
	m_gtDir = gtPrefix + "_GT";
	m_cameraPath = gtPrefix + ".camera.gt.txt";
	m_edgesPath = gtPrefix + ".edges.gt.txt";
	for (const auto& d : {m_imagesDir, m_gtDir})
	{
		std::error_code ec;
		fs::create_directories(d, ec);
		if (ec) throw std::runtime_error("cannot create folder '" + d + "': " + ec.message());
	}
	m_cameraGt.open(m_cameraPath);
	m_edgesGt.open(m_edgesPath);
	if (!m_cameraGt) throw std::runtime_error("cannot write '" + m_cameraPath + "'");
	if (!m_edgesGt) throw std::runtime_error("cannot write '" + m_edgesPath + "'");
	m_cameraGt << "# featloc-sim: left camera of " << m_cam.label
			   << " in the world at every stereo frame (TUM: t x y z qx qy qz qw; optical "
				  "axes x right, y down, z forward)\n";
	m_edgesGt << "# featloc-sim: vertical edges visible in each stereo frame of " << m_cam.label
			  << ". Image coordinates [px] are in the ideal (rectified, undistorted) images.\n"
				 "# frame t object s x y z_low z_high u_left_low v_left_low u_left_high "
				 "v_left_high u_right_low v_right_low u_right_high v_right_high visible_right\n";
}

mrpt::obs::CObservationStereoImages::Ptr StereoOutputWriter::write(
	size_t frame, double time, const StereoFrame& f, const std::vector<VisibleEdge>& edges)
{
	const std::string stem = fileStem(m_cam.label, frame);
	const std::string ext = "." + m_cam.image_format;
	const std::string leftName = stem + "_left" + ext, rightName = stem + "_right" + ext;
	for (const auto& [name, img] : {std::pair{leftName, &f.left}, std::pair{rightName, &f.right}})
	{
		const std::string path = (fs::path(m_imagesDir) / name).string();
		if (!cv::imwrite(path, *img)) throw std::runtime_error("cannot write '" + path + "'");
	}
	cv::Mat disp16(f.disparity.size(), CV_16U);
	f.disparity.convertTo(disp16, CV_16U, 256.0);
	const std::string dispPath = (fs::path(m_gtDir) / (stem + "_disparity.png")).string();
	if (!cv::imwrite(dispPath, disp16)) throw std::runtime_error("cannot write '" + dispPath + "'");

	const mrpt::poses::CPose3DQuat q(f.leftCamera);
	char row[512];
	std::snprintf(
		row, sizeof(row), "%.9f %.9f %.9f %.9f %.12f %.12f %.12f %.12f\n", time, q.x(), q.y(), q.z(),
		q.quat().x(), q.quat().y(), q.quat().z(), q.quat().r());
	m_cameraGt << row;
	for (const auto& e : edges)
	{
		std::snprintf(
			row, sizeof(row),
			"%zu %.9f %s %.4f %.6f %.6f %.4f %.4f %.3f %.3f %.3f %.3f %.3f %.3f %.3f %.3f %d\n",
			frame, time, e.edge.object.c_str(), e.edge.s, e.edge.x, e.edge.y, e.zLow, e.zHigh,
			e.uLeftLow, e.vLeftLow, e.uLeftHigh, e.vLeftHigh, e.uRightLow, e.vRightLow,
			e.uRightHigh, e.vRightHigh, e.visibleRight ? 1 : 0);
		m_edgesGt << row;
	}

	auto obs = std::make_shared<mrpt::obs::CObservationStereoImages>();
	obs->sensorLabel = m_cam.label;
	obs->timestamp = mrpt::Clock::fromDouble(time);
	obs->setStereoCameraParams(m_cam.stereoCamera());
	obs->cameraPose = mrpt::poses::CPose3DQuat(m_cam.leftCameraOnRobot());
	obs->hasImageRight = true;
	obs->imageLeft = mrpt::img::CImage(f.left, mrpt::img::DEEP_COPY);
	obs->imageRight = mrpt::img::CImage(f.right, mrpt::img::DEEP_COPY);
	// Stored by name: the rawlog keeps only the file names.
	obs->imageLeft.setExternalStorage(leftName);
	obs->imageRight.setExternalStorage(rightName);
	return obs;
}

std::string StereoOutputWriter::fileStem(const std::string& label, size_t frame)
{
	char number[32];
	std::snprintf(number, sizeof(number), "_%06zu", frame);
	return label + number;
}

void StereoOutputWriter::finish()
{
	m_cameraGt.flush();
	m_edgesGt.flush();
	if (!m_cameraGt) throw std::runtime_error("error writing '" + m_cameraPath + "'");
	if (!m_edgesGt) throw std::runtime_error("error writing '" + m_edgesPath + "'");
}
}  // namespace featloc
