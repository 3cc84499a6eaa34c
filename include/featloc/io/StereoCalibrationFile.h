#pragma once
#include <mrpt/img/TStereoCamera.h>
#include <mrpt/poses/CPose3D.h>

#include <string>

namespace featloc
{
/** A stereo calibration read from the files real datasets ship:
 *  - OpenCV / ROS camera_info YAML, one file per camera (`camera_matrix`,
 *    `distortion_coefficients`, `image_width`, `image_height`,
 *    `projection_matrix`), e.g. RTAB-Map's stereo_left.yaml and
 *    stereo_right.yaml: a rectified pair, the baseline from the right
 *    projection matrix (Tx = -fx * baseline);
 *  - the EuRoC / Kimera `sensor.yaml` per camera (`intrinsics` fu fv cu cv,
 *    `distortion_coefficients` k1 k2 p1 p2, `resolution`, `T_BS` the camera
 *    in the body frame, row-major 4x4): the right camera's pose relative
 *    to the left one comes from the two T_BS.
 * Both are read with cv::FileStorage (the files' "%YAML:1.0" dialect). */
struct StereoCalibrationFile
{
	mrpt::img::TStereoCamera stereo;  //!< intrinsics, lenses, right camera pose
	/** Left camera on the robot/body, optical axes (identity rotation
	 * plus the usual forward-looking turn when the files do not say). */
	mrpt::poses::CPose3D leftCameraOnBody;
	bool hasBodyPose = false;  //!< T_BS given (EuRoC/Kimera)
	std::string format;	 //!< "opencv" or "euroc"

	/** Throws InputError naming the file and key on a missing or bad
	 * value. */
	static StereoCalibrationFile load(const std::string& leftPath, const std::string& rightPath);
};
}  // namespace featloc
