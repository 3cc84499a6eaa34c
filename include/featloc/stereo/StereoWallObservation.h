#pragma once
#include <Eigen/Core>

#include <cstddef>
#include <string>

namespace featloc
{
/** A map wall as one stereo frame's disparity pixels place it, used as an
 * observation of the robot pose against the known map (featloc's
 * addition to Moon, Miura & Shirai 1999).
 *
 * The paper fits each reference plane to its disparity pixels (eq. 11)
 * only to constrain the features on it (3.1); the robot is then located by
 * features placed from a plane's boundary (3.3). Between a wall's ends no
 * boundary is in view, so a corridor's side wall gives the paper's method
 * nothing, although its fit says how far the camera is from the wall and
 * how it is turned to it. Here the fit's line is the measurement: z =
 * (a, b) of w = a + b s in the plane frame of the fit (PlaneFit), a frame
 * fixed to the robot; h(X) = the line the map's wall makes in that frame
 * seen from robot pose X = (x, y, yaw). The wall's length along itself is
 * not observed (b and a do not change when the robot slides along it). */
struct StereoWallObservation
{
	size_t wall = 0;  //!< the map wall (reference plane), as VerticalLandmarkObservation::wall
	std::string plane;	//!< its name in the map ("Wall.north#0")
	Eigen::Vector2d mapA = Eigen::Vector2d::Zero(), mapB = Eigen::Vector2d::Zero();	 //!< its ends, world [m]
	/** The fit's plane frame in the robot frame: origin [m], unit vector
	 * along the wall (s) and across it (w). */
	Eigen::Vector2d origin = Eigen::Vector2d::Zero(), e = Eigen::Vector2d::UnitX(), n = Eigen::Vector2d::UnitY();
	Eigen::Vector2d line = Eigen::Vector2d::Zero();	 //!< (a [m], b): PlaneFit::line
	Eigen::Matrix2d covariance = Eigen::Matrix2d::Identity();  //!< PlaneFit::lineCovariance
	double viewAngle = 0;  //!< [rad] PlanarRegion::viewAngle
	/** Share of the band above the camera in its visible columns that has
	 * its disparity pixels (PlanarRegion::bandPixels over bandRows). */
	double coverage = 0;

	/** h(X): the map wall's (a, b) in the plane frame from robot pose X,
	 * and optionally dh/dX (2x3). */
	Eigen::Vector2d predict(const Eigen::Vector3d& X, Eigen::Matrix<double, 2, 3>* H = nullptr) const;
};
}  // namespace featloc
