#pragma once
#include <utility>
#include <vector>

#include "featloc/eval/EvaluationReport.h"
#include "featloc/eval/Trajectory.h"

namespace featloc
{
/** Trajectory metrics against a reference:
 * - timestamp association (nearest, unique, within maxTimeDifference, as
 *   the TUM benchmark's associate.py);
 * - ATE: position RMSE (and mean, median...) after the rigid SE(2)
 *   alignment that minimises it (Sturm et al. 2012);
 * - RPE between consecutive associated poses: translation and rotation of
 *   (gt_i^-1 (+) gt_j)^-1 (+) (est_i^-1 (+) est_j);
 * - Kummerle et al. (2009) relations: the same error for given pairs
 *   (t1, t2) with reference relative poses;
 * - NEES, when the estimate has covariances (poses_cov.txt): e^T P^-1 e of
 *   every associated pose after the first, the estimate anchored at the
 *   first associated pose (not aligned: the alignment would absorb part of
 *   the error the covariance describes), with the share within the 95%
 *   chi-square bound for 3 dof (0.95 when the covariance is consistent). */
class TrajectoryEvaluator
{
   public:
	/** `align` false: the ATE without alignment, for estimates in the
	 * reference's frame (localization in a known map). */
	explicit TrajectoryEvaluator(double maxTimeDifference, bool align = true);

	/** Index pairs (reference, estimate), in increasing time. */
	std::vector<std::pair<size_t, size_t>> associate(
		const Trajectory& reference, const Trajectory& estimate) const;

	/** ATE and RPE. Throws InputError if fewer than two poses associate. */
	EvaluationReport evaluate(
		const Trajectory& reference, const Trajectory& estimate) const;

	/** Relation errors. Relations whose times have no estimate within
	 * maxTimeDifference are not counted (relationsMatched tells). Throws
	 * InputError when none matches. */
	EvaluationReport evaluateRelations(
		const std::vector<PoseRelation>& relations,
		const Trajectory& estimate) const;

   private:
	void neesOf(
		const Trajectory& reference, const Trajectory& estimate,
		const std::vector<std::pair<size_t, size_t>>& pairs, EvaluationReport& rep) const;

	double m_maxDt;
	bool m_align;
};
}  // namespace featloc
