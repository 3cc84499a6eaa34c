#pragma once
#include <mrpt/img/TStereoCamera.h>
#include <mrpt/obs/obs_frwds.h>
#include <mrpt/poses/poses_frwds.h>

#include <Eigen/Core>
#include <string>

namespace featloc
{
/** A rectified, level stereo pair as Moon, Miura & Shirai's 2-D method
 * sees it: vertical lines are points of the floor plan, and a point at
 * camera coordinates c = (c_x to the right, c_y ahead) [m] projects to the
 * columns (eq. 3, eq. 8 with 2B = baseline and the left camera as origin)
 *     x_l = cx + fx c_x / c_y,    x_r = cx + fx (c_x - B) / c_y,
 *     d = x_l - x_r = fx B / c_y.
 * The left camera sits on the robot at (camX, camY) with its optical axis
 * at camYaw, camZ above the floor. */
class StereoHead
{
   public:
	double fx = 0, fy = 0, cx = 0, cy = 0, baseline = 0;
	int width = 0, height = 0;
	double camX = 0, camY = 0, camYaw = 0, camZ = 0;

	/** From a checked observation: its left camera, the baseline (length
	 * of rightCameraPose) and cameraPose. Throws InputError (prefixed by
	 * `where`) when the camera looks more than max_tilt_deg up, down or
	 * sideways: vertical lines would not be vertical in the image. */
	static StereoHead fromObservation(
		const mrpt::obs::CObservationStereoImages& obs, const std::string& where,
		double maxTiltDeg = 10);
	/** The same from a calibration (left camera, baseline = length of
	 * rightCameraPose) and the left camera's pose on the robot (optical
	 * axes: z ahead, x right, y down). */
	static StereoHead fromCalibration(
		const mrpt::img::TStereoCamera& calibration, const mrpt::poses::CPose3D& cameraOnRobot,
		const std::string& where, double maxTiltDeg = 10);

	/** Camera coordinates of world point p seen from robot pose X = (x, y,
	 * yaw), and optionally d c / d X (2x3). */
	Eigen::Vector2d toCamera(
		const Eigen::Vector3d& X, const Eigen::Vector2d& p,
		Eigen::Matrix<double, 2, 3>* J = nullptr) const;
	/** World point of camera coordinates c from robot pose X. */
	Eigen::Vector2d toWorld(const Eigen::Vector3d& X, const Eigen::Vector2d& c) const;
	/** World direction of camera-frame direction v. */
	Eigen::Vector2d directionToWorld(const Eigen::Vector3d& X, const Eigen::Vector2d& v) const;

	/** Eq. (3): (x_l, x_r) of camera point c, and optionally d I / d c. */
	Eigen::Vector2d project(const Eigen::Vector2d& c, Eigen::Matrix2d* J = nullptr) const;
	/** The inverse: c from (x_l, x_r), and optionally d c / d (x_l, x_r). */
	Eigen::Vector2d triangulate(double xl, double xr, Eigen::Matrix2d* J = nullptr) const;
	/** Where the ray of left-image column u meets the line p + t dir
	 * (camera coordinates); false when they are parallel. */
	bool columnRayMeets(double u, const Eigen::Vector2d& p, const Eigen::Vector2d& dir, Eigen::Vector2d& c) const;
	/** Height above the floor of image row v at depth c_y (level camera). */
	double heightAt(double v, double depth) const { return camZ + (cy - v) * depth / fy; }
};
}  // namespace featloc
