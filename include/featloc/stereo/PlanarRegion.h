#pragma once
#include <opencv2/core/mat.hpp>

#include <string>

#include "featloc/stereo/PlaneFit.h"

namespace featloc
{
/** One reference plane (a wall of the map) as one stereo frame sees it:
 * where it was predicted (Moon, Miura & Shirai 1999, section 2.3.2), the
 * disparity pixels found on it (2.3.4) and the line fitted to them. */
struct PlanarRegion
{
	size_t wall = 0;  //!< index in the map
	/** Predicted left-image columns of the wall's two ends (a, b), and
	 * their standard deviations from the robot's uncertainty (eq. 5) and
	 * the image's (sigma_img). An end behind the camera or clipped by the
	 * near limit is not visible. */
	double uA = 0, uB = 0, sigmaUA = 0, sigmaUB = 0;
	bool aInView = false, bInView = false;	//!< the end's 3-sigma window is inside the image
	int uMin = 0, uMax = -1;  //!< columns searched (eq. 6)
	/** Left-image pixels whose disparity is within 3 sigma_d of the
	 * plane's (eqs. 9-10): 255, else 0. Full image size. */
	cv::Mat mask;
	size_t pixels = 0;
	/** Columns searched where, from the predicted pose itself, the ray
	 * meets this wall between its ends with no other wall of the map in
	 * front of it (1 cm), and the disparity pixels found in them higher
	 * than the camera: pixels elsewhere may be another surface's (in the
	 * 3-sigma margin around a corner, on a wall just in front), and below
	 * the camera a low surface's top is seen too. */
	size_t visibleColumns = 0, visiblePixels = 0;
	int visibleUMin = -1, visibleUMax = -1;	 //!< first and last of those columns (-1: none)
	/** Of those, the pixels in the band from the camera's height to 0.3 m
	 * above it, and the rows the band spans at the wall's depth summed over
	 * the visible columns: a wall at least that tall fills most of them; a
	 * low surface (a table) has none of its own there, only the block
	 * matcher's stray matches. */
	size_t bandPixels = 0;
	double bandRows = 0;
	/** Eq. (11) over those pixels alone (in the frame of `fit`; made,
	 * visibleFitted, when there are min_pixels of them): what a wall
	 * observation measures. The fit over every pixel is the features'
	 * plane (3.1). */
	bool visibleFitted = false;
	Eigen::Vector2d visibleLine = Eigen::Vector2d::Zero();
	Eigen::Matrix2d visibleLineCovariance = Eigen::Matrix2d::Zero();
	/** [rad] Mean angle between the view ray and the wall over the
	 * visible columns (pi/2: seen face on; near 0: at a grazing angle). */
	double viewAngle = 0;
	bool fitted = false;
	std::string reason;	 //!< why not fitted
	PlaneFit fit;
	double rms = 0;	 //!< [m] weighted RMS across the plane
	/** Squared Mahalanobis distance of the fitted line from the map's
	 * wall (robot and fit uncertainty); above chi2(2 dof, 3 sigma) the
	 * region is not the wall and is not fitted. */
	double mapDistance2 = 0;
};
}  // namespace featloc
