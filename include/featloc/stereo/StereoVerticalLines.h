#pragma once
#include <mrpt/img/TStereoCamera.h>
#include <mrpt/poses/CPose3D.h>

#include <opencv2/core/mat.hpp>
#include <string>
#include <vector>

#include "featloc/stereo/SadDisparity.h"
#include "featloc/stereo/SegmentMatch.h"
#include "featloc/stereo/SegmentStereoMatcher.h"
#include "featloc/stereo/SegmentTriangulator.h"
#include "featloc/stereo/VerticalSegment.h"
#include "featloc/stereo/VerticalSegmentDetector.h"
#include "featloc/stereo/WorldVerticalLine.h"

namespace featloc
{
/** Vertical-line landmarks of one rectified stereo pair without a map:
 * the segment stage of Moon, Miura & Shirai (2.1: detection, DP matching;
 * 2.2: the SAD disparity's support) and 3-D triangulation (SegmentTriangulator), placed in the world by a
 * known camera pose. What the paper's plane constraint (3.1) refines; used
 * on real pairs, where no map is at hand, to check that the segment stage
 * finds the same lines from two poses.
 *
 * The camera need not be level: each segment is triangulated in 3-D and
 * kept when its direction is within max_tilt_deg of the world's vertical.
 * The camera pose's own uncertainty (sigma_position per axis, sigma_
 * rotation per axis) is added to each line's covariance. */
class StereoVerticalLines
{
   public:
	struct Options
	{
		VerticalSegmentDetector::Options segments;
		SegmentStereoMatcher::Options matching;
		SadDisparity::Options sad;
		int num_disparities = 64;  //!< SAD search 0 .. num_disparities - 1
		double sigma_img = 0.5;	 //!< [px] column sigma (paper, 2.3.1)
		double max_tilt_deg = 10;  //!< 3-D direction from the world's vertical
		double min_depth = 0.3, max_depth = 8;	//!< [m]
		double sigma_position = 0;	//!< [m] camera pose, per axis
		double sigma_rotation_deg = 0;	//!< camera pose, per axis
	};

	struct Result
	{
		std::vector<VerticalSegment> left, right;
		std::vector<SegmentMatch> matches;
		cv::Mat disparity;	//!< 2.2, CV_32F, <= 0 invalid
		/** Per match: "" when the SAD disparity supports it, else why not. */
		std::vector<std::string> matchRejection;
		std::vector<WorldVerticalLine> lines;  //!< of the supported matches
	};

	StereoVerticalLines() = default;
	explicit StereoVerticalLines(const Options& o) : options(o) {}
	Options options;

	/** Grey rectified images, their calibration, and the left camera's
	 * pose in the world (optical axes: z ahead, x right, y down).
	 * Throws InputError, prefixed by `where`, without a usable calibration. */
	Result extract(
		const cv::Mat& left, const cv::Mat& right, const mrpt::img::TStereoCamera& calibration,
		const mrpt::poses::CPose3D& cameraInWorld, const std::string& where) const;

	/** The vertical lines of an extracted pair's supported matches placed
	 * by another camera pose (the image stages do not depend on it). */
	std::vector<WorldVerticalLine> place(const Result& extracted, const mrpt::img::TStereoCamera& calibration,
		const mrpt::poses::CPose3D& cameraInWorld, const std::string& where) const;
};
}  // namespace featloc
