#pragma once
#include <mrpt/math/TPose2D.h>

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "featloc/eval/ErrorStats.h"

namespace featloc
{
/** Errors of an estimated trajectory against a reference. Translations in
 * metres, rotations in radians (printed in degrees). */
struct EvaluationReport
{
	std::string reference, estimate;  //!< file names
	double maxTimeDifference = 0;  //!< [s] used for association
	/** One side has no times: rows were paired in order. */
	bool pairedByIndex = false;

	// Trajectory against trajectory.
	bool hasTrajectoryMetrics = false;
	size_t referencePoses = 0, estimatePoses = 0, associated = 0;
	/** Rigid SE(2) transform applied to the estimate (least squares on the
	 * associated positions, Horn's method via mrpt::tfest::se2_l2). */
	mrpt::math::TPose2D alignment;
	/** False: no alignment (identity), the estimate is taken in the
	 * reference's frame (localization in a known map). */
	bool aligned = true;
	ErrorStats ate;	 //!< absolute position error after alignment [m]
	ErrorStats ateRotation;	 //!< absolute yaw error after alignment [rad]
	ErrorStats rpeTranslation;	//!< consecutive associated poses [m]
	ErrorStats rpeRotation;	 //!< [rad]
	/** The RPE step by step: between reference poses `from` and `to`
	 * (indices of the reference, consecutive associated poses), for
	 * comparing two estimates of the same reference pair by pair
	 * (featloc-eval --paired-with). */
	struct StepError
	{
		size_t from = 0, to = 0;
		double translation = 0, rotation = 0;  //!< [m], [rad]
	};
	std::vector<StepError> rpeSteps;

	// Consistency, when the estimate has covariances.
	bool hasNees = false;
	ErrorStats nees;  //!< per pose: 3 on average if consistent
	double neesWithin95 = 0;  //!< share within chi2(3) 95%: 0.95 if consistent
	/** The bound of neesWithin95: the 95% quantile of chi-square with 3
	 * degrees of freedom. */
	static constexpr double kNeesBound95 = 7.815;
	/** Per pose: (estimate's time [s], NEES), in time order. */
	std::vector<std::pair<double, double>> neesSeries;

	// Relations (Kummerle et al. 2009).
	bool hasRelations = false;
	size_t relations = 0, relationsMatched = 0;
	ErrorStats relationTranslation;	 //!< |translation error| [m]
	ErrorStats relationRotation;  //!< |rotation error| [rad]

	/** Human-readable table. */
	std::string toText() const;
	/** JSON object. */
	std::string toJson() const;
	/** Writes neesSeries as "t nees" rows (for Monte Carlo consistency
	 * tests over several runs: scripts/bench-ekf.sh). Throws when the file
	 * cannot be written. */
	void writeNeesSeries(const std::string& path) const;

   private:
	/** The rows of writeNeesSeries() into `file`; `path` names it in errors. */
	void writeNeesRows(const std::string& file, const std::string& path) const;
};
}  // namespace featloc
