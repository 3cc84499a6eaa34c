#pragma once
#include <vector>
#include <mrpt/config/CConfigFileBase.h>
#include <opencv2/core/mat.hpp>

#include <Eigen/Core>
#include <string>

#include "featloc/io/WallMapFile.h"
#include "featloc/stereo/PlanarRegion.h"
#include "featloc/stereo/StereoHead.h"

namespace featloc
{
/** Planar surface extraction (Moon, Miura & Shirai 1999, section 2.3):
 * predicts where a reference plane of the map appears in the left image
 * and at what disparity, given the robot pose X with covariance Sigma_X,
 * collects the disparity pixels that agree, and fits the plane's line.
 *
 * - Columns (eqs. 3-6): the wall's ends, clipped to near_limit ahead of
 *   the camera, are projected; their sigma is sqrt(J Sigma_X J^T +
 *   sigma_img^2) and the search spans the ends' 3-sigma windows.
 * - Disparity (eqs. 7-10): at each column the ray meets the predicted wall
 *   at depth c_y, d = fx B / c_y, and sigma_d^2 = dD/dX Sigma_X dD/dX^T +
 *   2 sigma_img^2. Pixels with |d_pixel - d| <= window_sigmas * sigma_d
 *   are the plane's, unless they lie below min_height or above
 *   max_height (the floor and the ceiling).
 * - Fit (eq. 11, see PlaneFit): weighted least squares, each pixel's
 *   variance across the plane from its disparity's (sigma_nu^2 =
 *   2 sigma_img^2). Neighbouring SAD disparities share most of their
 *   block_size x block_size window and are not independent: the
 *   covariance is multiplied by the pixels per window (block_size^2)
 *   and by the reduced chi^2 when it exceeds 1. */
class PlanarRegionExtractor
{
   public:
	struct Options
	{
		double sigma_img = 0.5;	 //!< [px] (paper, 2.3.1)
		double window_sigmas = 3;  //!< (paper, eq. 6)
		double near_limit = 0.3;  //!< [m]
		unsigned int min_pixels = 300;
		int block_size = 15;  //!< of the SAD matcher, for the correlation of neighbours
		/** [m] Points below min_height or above max_height are left out:
		 * the floor and the ceiling are not walls of a 2-D map, and their
		 * pixels at the wall's disparity (the floor just in front of it)
		 * would pull the fit towards the camera. */
		double min_height = 0.1, max_height = 2.4;
	};

	PlanarRegionExtractor() = default;
	explicit PlanarRegionExtractor(const Options& o) : options(o) {}
	Options options;

	/** The disparities the wall can show in the image (eqs. 9-10): its
	 * part inside the field of view and beyond near_limit, its ends'
	 * disparities +- window_sigmas sigma_d. False when none of it is in
	 * view. */
	bool disparityRange(
		const MapWall& wall, const StereoHead& head, const Eigen::Vector3d& X,
		const Eigen::Matrix3d& SigmaX, double& dMin, double& dMax) const;

	/** Per image column, the depth [m] at which its ray first meets a
	 * wall of `walls` (beyond near_limit; +inf where none): what the map
	 * says hides what. */
	std::vector<double> nearestWallDepth(
		const std::vector<MapWall>& walls, const StereoHead& head, const Eigen::Vector3d& X) const;

	/** `disparity`: CV_32F left-image disparities, <= 0 where invalid.
	 * `nearest` (from nearestWallDepth, optional): columns where another
	 * wall of the map is nearer than this one, over the whole 3-sigma
	 * window of the column, are occluded and not searched (the paper's
	 * scene has nothing in front of its planes; a room has desks). */
	PlanarRegion extract(
		const MapWall& wall, size_t wallIndex, const StereoHead& head, const Eigen::Vector3d& X,
		const Eigen::Matrix3d& SigmaX, const cv::Mat& disparity,
		const std::vector<double>* nearest = nullptr) const;
};
}  // namespace featloc
