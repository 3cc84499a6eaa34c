#pragma once
#include <Eigen/Core>

#include <string>

namespace featloc
{
/** A vertical segment modelled on a reference plane (Moon, Miura & Shirai
 * 1999, section 3.3): one row of the paper's Table 1. */
struct ModelledFeature
{
	size_t wall = 0;  //!< reference plane (index in the map)
	std::string plane;	//!< its name
	int index = 0;	//!< 1-based, counted from the plane's boundary
	size_t match = 0;  //!< index of the stereo match it comes from
	/** Eq. (15): world position on the plane [m], and eq. (17): its
	 * rank-1 covariance along the plane. */
	Eigen::Vector2d position = Eigen::Vector2d::Zero();
	Eigen::Matrix2d covariance = Eigen::Matrix2d::Zero();
	/** The boundary's part of `covariance`, shared by every feature placed
	 * from that boundary in the frame. */
	Eigen::Matrix2d sharedCovariance = Eigen::Matrix2d::Zero();
	double dp = 0, sigmaDp = 0;	 //!< [m] distance from the boundary along the plane
	double lLow = 0, lHigh = 0;	 //!< [m] height of its ends above the floor
	double lengthSimilarity = 0;  //!< eq. (18)
	bool selected = false;
	std::string reason;	 //!< why not selected
	/** The same segment triangulated without the plane constraint, in the
	 * world frame (stereo and robot uncertainty), for comparison. */
	Eigen::Vector2d unconstrained = Eigen::Vector2d::Zero();
	Eigen::Matrix2d unconstrainedCovariance = Eigen::Matrix2d::Zero();

	double length() const { return lHigh - lLow; }
};
}  // namespace featloc
