#pragma once
#include <cmath>
#include <string>
#include <vector>

#include "featloc/io/WallMapFile.h"
#include "featloc/stereo/BoundarySearch.h"
#include "featloc/stereo/PlanarRegionExtractor.h"
#include "featloc/stereo/SadDisparity.h"
#include "featloc/stereo/SegmentStereoMatcher.h"
#include "featloc/stereo/StereoLandmarkExtractor.h"
#include "featloc/stereo/StereoVerticalLines.h"
#include "featloc/stereo/VerticalSegmentDetector.h"

namespace featloc
{
/** Moon, Miura & Shirai (IROS 1999), "On-line selection of stable visual
 * landmarks under uncertainty", sections 2-4, on one stereo pair:
 *
 *  1. vertical segments in both images (VerticalSegmentDetector, 2.1),
 *     matched by dynamic programming (SegmentStereoMatcher, 2.1);
 *  2. an SAD disparity image, 15x15, both directions with the left-right
 *     check of eq. (2): OpenCV's StereoBM with disp12MaxDiff 1, over the
 *     disparities the visible walls of the map can show (2.3.3); a match
 *     whose disparity the image does not support (median of the valid
 *     disparities in a band around the left segment more than
 *     disparity_tolerance_px away, or too few valid ones) is dropped (2.2);
 *  3. the map's walls as reference planes: predicted region, disparity
 *     pixels and line fit (PlanarRegionExtractor, 2.3);
 *  4. the matches on a plane (most of the band in its region, within
 *     3 sigma of the wall's extent; the best fitting plane, and of
 *     collinear walls fitting as well the shortest: a whiteboard rather
 *     than the wall it hangs on) (2.4), each constrained to it by the Kalman update
 *     of eqs. (12)-(14) (PlaneFit::constrain, 3.1);
 *  5. the plane's boundary at a visible end (BoundarySearch, 3.2), put on
 *     the plane the same way, and each feature's position relative to it,
 *     eqs. (15)-(17) (3.3);
 *  6. every match on a plane, boundary or not, becomes an observation for
 *     the EKF (section 5), with its ends' heights (an end at the image
 *     border is not observed); a selected feature may start a landmark;
 *  7. selection (4): a feature within boundary_sigmas sigma of the
 *     boundary (|d_p| < 3 sigma_dp), or whose left and right segments'
 *     length similarity (eq. 18) is below min_length_similarity, is not a
 *     landmark; the reason is kept.
 * Parameters: [StereoLandmarks.StableVerticalLandmarks] (doc/config-reference.md). */
class StableVerticalLandmarks : public StereoLandmarkExtractor
{
	DEFINE_MRPT_OBJECT(StableVerticalLandmarks, featloc)

   public:
	struct Options
	{
		std::string map;  //!< wall map file (world file or segment list)
		VerticalSegmentDetector::Options segments;
		SegmentStereoMatcher::Options matching;
		int block_size = 15;  //!< SAD window (paper: 15x15)
		/** Most disparities the SAD searches, a multiple of 16. Each frame
		 * searches only the range the map's visible walls can show
		 * (eqs. 9-10), rounded up to 16, within this. */
		int num_disparities = 128;
		int uniqueness_ratio = 5;  //!< StereoBM's, [%]
		int texture_threshold = 10;	 //!< StereoBM's
		double disparity_tolerance_px = 1.5;
		double sigma_img = 0.5;	 //!< [px] paper, 2.3.1
		double window_sigmas = 3;  //!< paper, eq. (6)
		unsigned int min_plane_pixels = 300;
		double min_height = 0.1, max_height = 2.4;	//!< [m] band of wall points used (2.3)
		double boundary_sigmas = 3;	 //!< paper, section 4
		/** [deg] least angle between the view ray and the wall at an end
		 * for its boundary to be searched (featloc's addition). */
		double min_boundary_angle_deg = 20;
		bool snap_to_segment = true;
		/** [px] sigma of a segment end's row: the ends' heights in the
		 * EKF's observations (section 5). */
		double sigma_end_px = 2;
		double min_length_similarity = 0.7;	 //!< paper, section 4 (threshold not given)
		/** Hand the EKF every fitted wall as an observation of the robot
		 * pose (StereoWallObservation; featloc's addition: the paper uses
		 * the fit only to constrain the features on it). */
		bool wall_observations = true;
		/** [deg] Least mean angle between the view rays and a wall for its
		 * fit to be a wall observation. */
		double wall_min_view_angle_deg = 45;
	};
	Options options;
	std::vector<MapWall> walls;	 //!< loaded from options.map

	void loadParams(const mrpt::config::CConfigFileBase& cfg, const std::string& section) override;
	void saveParams(mrpt::config::CConfigFileBase& cfg, const std::string& section) const override;
	/** The map is required. */
	void requireComplete(const mrpt::config::CConfigFileBase& cfg, const std::string& section) const override;

	std::string planeName(size_t wall) const override
	{
		return wall < walls.size() ? walls[wall].name : StereoLandmarkExtractor::planeName(wall);
	}
	std::string mapFile() const override { return m_mapPath; }

	StereoLandmarkFrame process(
		const cv::Mat& left, const cv::Mat& right, const StereoHead& head,
		const mrpt::poses::CPosePDFGaussian& robot) const override;

	/** Whether the map carries wall w's plane on past its end a (or b):
	 * another wall within kCoplanarAngle and kCoplanarDistance of its
	 * line covers the end and continues beyond it (a whiteboard on a
	 * wall). Only there may an intensity edge alone be the boundary. */
	bool continuesCoplanar(size_t w, bool atA) const;
	/** Whether the depth step at plane `pl`'s end a (or b), `depth` ahead,
	 * can be seen from the predicted pose: beyond it, over the window and
	 * the evidence the boundary search (`search`) looks at, the map's nearest wall
	 * (`nearest`, PlanarRegionExtractor::nearestWallDepth) lies behind the
	 * plane by kEndStepPx of disparity. A wall meeting it at a corner or
	 * standing just behind it leaves the block matcher no step to see; one
	 * in front hides the end (featloc's check). */
	bool endStepVisible(const PlanarRegion& pl, bool atA, double depth, const StereoHead& head,
		const std::vector<double>& nearest, const BoundarySearch::Options& search) const;
	/** Whether walls w and k lie on one line (within kCoplanarAngle and
	 * kCoplanarDistance). */
	bool collinear(size_t w, size_t k) const;
	static constexpr double kCoplanarAngle = 2 * M_PI / 180, kCoplanarDistance = 0.05;
	/** [m] How far a collinear wall must go on past an end for the plane
	 * to go on there (continuesCoplanar). */
	static constexpr double kCoplanarContinuation = 0.2;
	/** [px] Least disparity by which the map's nearest wall beyond a
	 * plane's end must lie behind it for the end to be searched. */
	static constexpr double kEndStepPx = 2;
	/** A fitted wall is a wall observation only when it is the nearest
	 * wall, from the predicted pose, in this many columns
	 * (PlanarRegion::visibleColumns) with min_plane_pixels in them. */
	static constexpr size_t kMinWallColumns = 20;
	/** ... and when its pixels above the camera fill this share of the
	 * rows a wall max_height tall would fill there (StereoWallObservation::coverage). */
	static constexpr double kMinWallCoverage = 0.5;

	/** The SAD disparity image of stage 2 alone (CV_32F, <= 0 invalid),
	 * searching minDisparity .. minDisparity + numDisparities - 1 (0: the
	 * option's whole range). */
	cv::Mat disparity(const cv::Mat& left, const cv::Mat& right, int minDisparity = 0, int numDisparities = 0) const;
	/** Stage 2 with this extractor's options. */
	SadDisparity sad() const;
	/** Stages 2.1-2.2 alone (StereoVerticalLines, no map) with this
	 * extractor's options: what featloc-viewer redraws for a pair. */
	StereoVerticalLines::Options segmentStageOptions() const;

   private:
	std::string m_mapPath;	//!< options.map resolved
};
}  // namespace featloc
