#pragma once
#include <mrpt/config/CLoadableOptions.h>
#include <mrpt/img/TStereoCamera.h>
#include <mrpt/poses/CPose3D.h>

#include <string>
#include <vector>

#include "featloc/stereo/StereoHead.h"

namespace featloc
{
/** `[StereoCamera]` of a world file: a rectified stereo head on the robot.
 * Without the section (or with `enabled = false`) nothing is rendered and
 * the rawlog is byte-identical to a world without a camera.
 *
 * Both cameras share the pinhole intrinsics; the right one sits
 * `baseline` metres to the right of the left one along the image x axis
 * (a rectified pair). `pose` places the left camera on the robot: x y z
 * [m], then yaw, pitch, roll [deg] of its viewing direction (yaw 0 looks
 * along the robot's x axis, positive pitch looks down, roll turns the
 * image about the optical axis).
 *
 * Image effects, in the order applied: optical blur (Gaussian, sigma in
 * pixels), a gain per image and frame (1 + N(0, gain_change^2), as two
 * free-running auto-gains), pixel noise N(0, noise_sigma^2) grey levels,
 * rounding to 8 bits. With `distortion` the images are rendered through
 * that radial-tangential lens (OpenCV's k1 k2 p1 p2 k3), and the same
 * coefficients go into the rawlog's calibration, so a reader must rectify
 * to get the ideal pinhole images back. */
struct StereoCameraOptions : public mrpt::config::CLoadableOptions
{
	static constexpr const char* kSection = "StereoCamera";

	bool enabled = false;  //!< true when the world file has the section
	std::string label = "STEREO";  //!< sensor label in the rawlog
	unsigned int width = 640, height = 480;	 //!< [px]
	double fx = 500, fy = 500;	//!< [px] focal lengths
	double cx = 319.5, cy = 239.5;	//!< [px] principal point
	double baseline = 0.12;	 //!< [m] left to right camera
	/** Left camera on the robot: x y z [m], yaw pitch roll [rad] (degrees
	 * in the file). */
	std::vector<double> pose = {0.1, 0, 1.0, 0, 0, 0};
	double rate = 5;  //!< [Hz] stereo pairs per second
	double noise_sigma = 2.0;  //!< [grey levels] pixel noise
	double blur_sigma = 0.5;  //!< [px] optical blur; 0 = none
	double gain_change = 0.02;	//!< relative gain sigma per image and frame
	/** Lens distortion k1 k2 p1 p2 k3; all zero = ideal pinhole. */
	std::vector<double> distortion = {0, 0, 0, 0, 0};
	double ceiling_height = 2.7;  //!< [m] the ceiling plane
	/** Image files: "png" (lossless) or "jpg". */
	std::string image_format = "png";

	bool hasDistortion() const;
	/** Left camera pose on the robot, camera axes as MRPT and OpenCV use
	 * them (x right, y down, z forward). */
	mrpt::poses::CPose3D leftCameraOnRobot() const;
	/** The calibration written into each CObservationStereoImages. */
	mrpt::img::TStereoCamera stereoCamera() const;
	/** The head as the stereo landmark extractor sees it (a level camera
	 * is required; throws InputError naming [StereoCamera] otherwise). */
	StereoHead head() const { return StereoHead::fromCalibration(stereoCamera(), leftCameraOnRobot(), "[StereoCamera]"); }

	void loadFromConfigFile(
		const mrpt::config::CConfigFileBase& c, const std::string& s) override;
	void saveToConfigFile(
		mrpt::config::CConfigFileBase& c, const std::string& s) const override;
};
}  // namespace featloc
