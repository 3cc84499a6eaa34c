#pragma once
#include <opencv2/core/mat.hpp>

#include <string>
#include <vector>

#include "featloc/stereo/VerticalLandmarkObservation.h"
#include "featloc/stereo/BoundarySearch.h"
#include "featloc/stereo/ModelledFeature.h"
#include "featloc/stereo/PlanarRegion.h"
#include "featloc/stereo/SegmentMatch.h"
#include "featloc/stereo/StereoWallObservation.h"
#include "featloc/stereo/VerticalSegment.h"

namespace featloc
{
/** Everything one stereo pair gave the landmark extractor, stage by stage
 * (for the outputs, the debug pictures and the tests). */
struct StereoLandmarkFrame
{
	std::vector<VerticalSegment> left, right;  //!< 2.1
	std::vector<SegmentMatch> matches;	//!< 2.1, DP
	/** Per match: "" when the disparity image supports it (2.2), else why not. */
	std::vector<std::string> matchRejection;
	cv::Mat disparity;	//!< 2.2, CV_32F, <= 0 invalid
	int sadMin = 0, sadRange = 0;  //!< disparities searched: sadMin .. sadMin + sadRange - 1
	std::vector<PlanarRegion> planes;  //!< 2.3, every map wall tried
	/** Per plane: the boundary found (3.2), and at which end. */
	std::vector<BoundarySearch::Result> boundaries;
	/** Per plane (zero where it has no features): how far, along the wall, the features
	 * placed from the boundary lie from their own stereo positions
	 * (weighted mean) and that offset's sigma if the boundary is the
	 * map's edge [m]. Beyond window_sigmas sigma the boundary is rejected. */
	struct BoundaryCheck
	{
		double offset = 0, sigma = 0;
	};
	std::vector<BoundaryCheck> boundaryOffsets;
	std::vector<ModelledFeature> features;	//!< 3.3 and 4
	/** Every match on a plane (2.4), constrained to it (3.1), boundary
	 * found or not: the EKF's observations (section 5); the selected
	 * features among them may start landmarks. */
	std::vector<VerticalLandmarkObservation> observations;
	/** Every map wall whose plane was fitted (2.3), as an observation of
	 * the robot pose against the map (featloc's addition, option
	 * wall_observations); empty when that is off. */
	std::vector<StereoWallObservation> walls;
	double seconds = 0, disparitySeconds = 0;
};
}  // namespace featloc
