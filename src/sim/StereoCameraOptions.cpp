#include "featloc/sim/StereoCameraOptions.h"

#include <mrpt/core/bits_math.h>

#include <algorithm>
#include <cmath>

#include "featloc/config/ConfigValues.h"

namespace featloc
{
bool StereoCameraOptions::hasDistortion() const
{
	return std::any_of(distortion.begin(), distortion.end(), [](double d) { return d != 0; });
}

mrpt::poses::CPose3D StereoCameraOptions::leftCameraOnRobot() const
{
	// A body-like frame (x forward, y left, z up) turned by yaw, pitch and
	// roll, then the fixed turn to optical axes (z forward, x right, y down).
	const mrpt::poses::CPose3D body(pose[0], pose[1], pose[2], pose[3], pose[4], pose[5]);
	const mrpt::poses::CPose3D toOptical(
		0, 0, 0, mrpt::DEG2RAD(-90.0), 0, mrpt::DEG2RAD(-90.0));
	return body + toOptical;
}

mrpt::img::TStereoCamera StereoCameraOptions::stereoCamera() const
{
	mrpt::img::TStereoCamera sc;
	for (auto* cam : {&sc.leftCamera, &sc.rightCamera})
	{
		cam->ncols = width;
		cam->nrows = height;
		cam->setIntrinsicParamsFromValues(fx, fy, cx, cy);
		if (hasDistortion())
			cam->setDistortionPlumbBob(
				distortion[0], distortion[1], distortion[2], distortion[3], distortion[4]);
		else
			cam->distortion = mrpt::img::DistortionModel::none;
		cam->focalLengthMeters = 0.004;	 // unknown; MRPT only displays it
	}
	sc.leftCamera.cameraName = label + "_LEFT";
	sc.rightCamera.cameraName = label + "_RIGHT";
	sc.rightCameraPose = mrpt::math::TPose3DQuat(baseline, 0, 0, 1, 0, 0, 0);
	return sc;
}

void StereoCameraOptions::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	using namespace featloc::config;
	enabled = c.sectionExists(s);
	read(c, s, "enabled", enabled);
	read(c, s, "label", label);
	read(c, s, "width", width);
	read(c, s, "height", height);
	read(c, s, "fx", fx);
	read(c, s, "fy", fy);
	read(c, s, "cx", cx);
	read(c, s, "cy", cy);
	read(c, s, "baseline", baseline);
	std::vector<double> p = {pose[0], pose[1], pose[2], mrpt::RAD2DEG(pose[3]),
		mrpt::RAD2DEG(pose[4]), mrpt::RAD2DEG(pose[5])};
	read(c, s, "pose", p);
	require(p.size() == 6, c, s, "pose", "[x y z yaw_deg pitch_deg roll_deg]");
	pose = {p[0], p[1], p[2], mrpt::DEG2RAD(p[3]), mrpt::DEG2RAD(p[4]), mrpt::DEG2RAD(p[5])};
	read(c, s, "rate", rate);
	read(c, s, "noise_sigma", noise_sigma);
	read(c, s, "blur_sigma", blur_sigma);
	read(c, s, "gain_change", gain_change);
	read(c, s, "distortion", distortion);
	read(c, s, "ceiling_height", ceiling_height);
	readChoice(c, s, "image_format", image_format, {"png", "jpg"});
	require(!label.empty(), c, s, "label", "a non-empty label");
	require(width >= 16 && width <= 8192, c, s, "width", "in [16, 8192]");
	require(height >= 16 && height <= 8192, c, s, "height", "in [16, 8192]");
	require(fx > 0 && std::isfinite(fx), c, s, "fx", "> 0");
	require(fy > 0 && std::isfinite(fy), c, s, "fy", "> 0");
	require(std::isfinite(cx) && cx >= 0 && cx <= width, c, s, "cx", "in [0, width]");
	require(std::isfinite(cy) && cy >= 0 && cy <= height, c, s, "cy", "in [0, height]");
	require(baseline > 0 && baseline < 10, c, s, "baseline", "in (0, 10) m");
	require(rate > 0 && rate <= 1000, c, s, "rate", "in (0, 1000] Hz");
	require(noise_sigma >= 0, c, s, "noise_sigma", ">= 0");
	require(blur_sigma >= 0 && blur_sigma <= 20, c, s, "blur_sigma", "in [0, 20] px");
	require(gain_change >= 0 && gain_change < 0.5, c, s, "gain_change", "in [0, 0.5)");
	require(distortion.size() == 5, c, s, "distortion", "five numbers [k1 k2 p1 p2 k3]");
	require(
		std::abs(p[4]) < 80 && std::abs(p[5]) < 80, c, s, "pose",
		"pitch and roll within +-80 deg (a camera looking at the walls)");
	require(p[2] > 0 && p[2] < ceiling_height, c, s, "pose", "z between the floor and the ceiling");
	require(ceiling_height > 0, c, s, "ceiling_height", "> 0");
}

void StereoCameraOptions::saveToConfigFile(
	mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	using namespace featloc::config;
	write(c, s, "enabled", enabled, "render a stereo pair (the section's presence enables it)");
	write(c, s, "label", label, "sensor label of the CObservationStereoImages");
	write(c, s, "width", width, "[px]");
	write(c, s, "height", height, "[px]");
	write(c, s, "fx", fx, "[px] focal length, both cameras");
	write(c, s, "fy", fy, "[px]");
	write(c, s, "cx", cx, "[px] principal point");
	write(c, s, "cy", cy, "[px]");
	write(c, s, "baseline", baseline, "[m] right camera to the right of the left one");
	write(c, s, "pose",
		std::vector<double>{pose[0], pose[1], pose[2], mrpt::RAD2DEG(pose[3]),
			mrpt::RAD2DEG(pose[4]), mrpt::RAD2DEG(pose[5])},
		"[m m m deg deg deg] left camera on the robot: x y z yaw pitch(+ down) roll");
	write(c, s, "rate", rate, "[Hz] stereo pairs per second");
	write(c, s, "noise_sigma", noise_sigma, "[grey levels] Gaussian pixel noise");
	write(c, s, "blur_sigma", blur_sigma, "[px] Gaussian optical blur; 0 = none");
	write(c, s, "gain_change", gain_change, "relative gain sigma, per image and frame");
	write(c, s, "distortion", distortion, "k1 k2 p1 p2 k3 (OpenCV); zeros = ideal pinhole");
	write(c, s, "ceiling_height", ceiling_height, "[m]");
	write(c, s, "image_format", image_format, "png | jpg (files in <rawlog>_Images/)");
}
}  // namespace featloc
