#pragma once
#include <Eigen/Core>

#include <cstddef>

namespace featloc
{
/** One vertical line segment seen by the stereo front end on a map wall
 * (Moon, Miura & Shirai 1999): the observation L_t of the constraint of
 * eq. (20) for a landmark [x y l_low l_high].
 *
 * The position is the segment's point after the plane constraint of
 * section 3.1 (eqs. 12-14), in the robot frame: it depends on the robot
 * pose through the landmark's world position only. The heights of its ends
 * are independent of the pose (a level camera). */
struct VerticalLandmarkObservation
{
	size_t wall = 0;  //!< the map wall (reference plane) it lies on
	int polarity = 0;  //!< of its edge in the left image (+1 darker on the left)
	Eigen::Vector2d position = Eigen::Vector2d::Zero();	 //!< robot frame [m]
	Eigen::Matrix2d covariance = Eigen::Matrix2d::Identity();  //!< [m^2]
	/** The plane constraint's share of that error, common to every
	 * observation of the same wall in the frame (one fitted plane, eq. 11):
	 * Cov(position_i, position_j) = J_i planeCovariance J_j^T with J =
	 * planeJacobian = d position / d (a, b). Without it the EKF counts one
	 * plane fit N times. */
	Eigen::Matrix2d planeJacobian = Eigen::Matrix2d::Zero();
	Eigen::Matrix2d planeCovariance = Eigen::Matrix2d::Zero();
	double lLow = 0, lHigh = 0;	 //!< [m] heights of its ends above the floor
	/** [m] their sigmas; 0 where the end is not observed (the segment
	 * reaches the image border: the line goes on beyond it). */
	double sigmaLow = 0, sigmaHigh = 0;
	/** A selected feature (section 4) may start a landmark: its position
	 * relative to the map's edge, eq. (15), with the rank-1 covariance of
	 * eq. (17), world frame. It does not depend on the robot pose. */
	bool canStart = false;
	Eigen::Vector2d start = Eigen::Vector2d::Zero();
	Eigen::Matrix2d startCovariance = Eigen::Matrix2d::Zero();
	/** The part of startCovariance that every feature of this frame placed
	 * from the same boundary of the same wall shares: the boundary's own
	 * error along the wall (e' P_b e, section 3.3). Eq. (17) leaves it out
	 * of the features' joint covariance; their starts are correlated by it
	 * (on moon-lab it is 20 mm rms, the features' own part 8 mm). */
	Eigen::Matrix2d startSharedCovariance = Eigen::Matrix2d::Zero();
	size_t match = 0;  //!< the stereo match it comes from (StereoLandmarkFrame::matches)
};
}  // namespace featloc
