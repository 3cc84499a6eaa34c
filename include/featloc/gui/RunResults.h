#pragma once
#include <mrpt/math/CMatrixFixed.h>
#include <mrpt/math/TPoint2D.h>
#include <mrpt/math/TPose2D.h>
#include <mrpt/obs/obs_frwds.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "featloc/eval/EvaluationOptions.h"
#include "featloc/eval/Trajectory.h"
#include "featloc/io/MatchTableFile.h"

namespace featloc
{
struct DecodedStereoPair;

/** Everything featloc-viewer shows of one run, read from its results folder
 * by RunResultsLoader. Steps are in time order; a step's scan and match are
 * null / -1 when the run had none for it. */
struct RunResults
{
	struct Step
	{
		double t = 0;  //!< [s]
		mrpt::math::TPose2D pose;  //!< estimated robot pose (world frame)
		mrpt::math::CMatrixDouble33 cov;
		/** The step's scan (from estimated.rawlog), or null. */
		std::shared_ptr<mrpt::obs::CObservation2DRangeScan> scan;
		int match = -1;	 //!< index into `matches`, or -1
		int reference = -1;	 //!< step of the match's reference scan, or -1
	};
	/** A stereo pair of the run (from estimated.rawlog) at a step. */
	struct StereoFrame
	{
		size_t step = 0;
		std::shared_ptr<mrpt::obs::CObservationStereoImages> observation;
		std::shared_ptr<const DecodedStereoPair> images;
		/** The run's own picture of this step (stereo_debug/NNNNNN.png,
		 * written every [Output] stereo_debug_every steps), or "". */
		std::string debugPicture;
	};
	struct Landmark
	{
		double x = 0, y = 0;  //!< [m] world frame
		double cxx = 0, cxy = 0, cyy = 0;  //!< [m^2]
	};

	std::string folder;	 //!< the results folder read
	std::string estimator;	//!< from summary.json ("ekf", "matcher", ...)
	std::string matcherClass;  //!< from config_used.ini
	std::string configPath;	 //!< config_used.ini, "" if missing
	std::vector<Step> steps;
	std::vector<MatchTableFile::Row> matches;
	std::optional<Trajectory> groundTruth;
	/** Takes ground-truth poses into the estimate's frame: the inverse of
	 * the SE(2) alignment featloc-run applied to the estimate before its ATE
	 * (summary.json evaluation.alignment; identity without one). */
	mrpt::math::TPose2D groundTruthToEstimate;
	/** The run's evaluation pairing tolerance (summary.json
	 * evaluation.max_time_difference_s) [s]. */
	double maxTimeDifference = EvaluationOptions().max_time_difference;
	/** nees.txt rows: time [s], NEES (3 dof). */
	std::vector<std::pair<double, double>> nees;
	std::vector<Landmark> landmarks;
	std::vector<StereoFrame> stereo;  //!< in step order
	/** The run's [StereoLandmarks] class and configuration, for the
	 * stereo page's segment stage ("" without stereo). */
	std::string stereoExtractorClass;
	/** What could not be read, one sentence each naming the file: the
	 * viewer opens what it can and shows these. */
	/** Localization in a known map: the map's occupied cells (map frame,
	 * which is the estimate's), read again from the file the run used. */
	std::vector<mrpt::math::TPoint2D> mapCells;
	std::vector<std::string> problems;

	/** The step whose time is nearest to t (steps must not be empty). */
	size_t stepNearest(double t) const;
	/** The step at time t: an output row and a rawlog observation of the
	 * same step agree to the microsecond (both are one mrpt::Clock value). */
	std::optional<size_t> stepAt(double t) const;
	/** The stereo frame of step i, or nullptr. */
	const StereoFrame* stereoAt(size_t step) const;
};
}  // namespace featloc
