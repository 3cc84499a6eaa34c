#include "featloc/eval/TrajectoryEvaluator.h"

#include <Eigen/Dense>

#include <mrpt/math/wrap2pi.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/tfest/se2.h>

#include <algorithm>
#include <cmath>
#include <tuple>

#include "featloc/core/InputError.h"
#include "featloc/math/PoseDifference.h"

namespace featloc
{
namespace
{
using mrpt::poses::CPose2D;

CPose2D asPose(const TimedPose& p) { return CPose2D(p.pose); }

/** Index of the pose nearest in time to t, or npos if none within maxDt. */
size_t nearest(const Trajectory& traj, double t, double maxDt)
{
	const auto& v = traj.poses;
	const auto it = std::lower_bound(
		v.begin(), v.end(), t,
		[](const TimedPose& p, double tt) { return p.t < tt; });
	size_t best = std::string::npos;
	double bestDt = maxDt;
	if (it != v.end() && it->t - t <= bestDt)
	{
		best = static_cast<size_t>(it - v.begin());
		bestDt = it->t - t;
	}
	if (it != v.begin() && t - std::prev(it)->t <= bestDt)
		best = static_cast<size_t>(std::prev(it) - v.begin());
	return best;
}

/** Translation and |rotation| of (a^-1 (+) b)^-1 (+) (c^-1 (+) d): the
 * error of the estimated relative motion c->d against the reference a->b. */
std::pair<double, double> relativeError(
	const CPose2D& refDelta, const CPose2D& estDelta)
{
	const CPose2D err = estDelta - refDelta;	// refDelta^-1 (+) estDelta
	return {std::hypot(err.x(), err.y()),
		std::abs(mrpt::math::wrapToPi(err.phi()))};
}
}  // namespace

TrajectoryEvaluator::TrajectoryEvaluator(double maxTimeDifference, bool align)
	: m_maxDt(maxTimeDifference), m_align(align)
{
}

std::vector<std::pair<size_t, size_t>> TrajectoryEvaluator::associate(
	const Trajectory& reference, const Trajectory& estimate) const
{
	if (!reference.timed || !estimate.timed)
	{
		// No times on one side: the i-th rows describe the same step.
		std::vector<std::pair<size_t, size_t>> pairs;
		for (size_t i = 0; i < std::min(reference.poses.size(), estimate.poses.size()); i++)
			pairs.emplace_back(i, i);
		return pairs;
	}
	for (const Trajectory* t : {&reference, &estimate})
		if (t->repeatedTimes)
			throw InputError(
				"'" + t->source +
				"' has rows that share a time, so they cannot be paired by time; compare it "
				"with an untimed reference (MRPT robot path or KITTI file: rows are paired in "
				"order)");
	// Candidate pairs (|dt|, ref, est): each estimate with its nearest
	// reference; then greedily keep the closest pairs with unique indices.
	std::vector<std::tuple<double, size_t, size_t>> cand;
	for (size_t e = 0; e < estimate.poses.size(); e++)
	{
		const size_t r = nearest(reference, estimate.poses[e].t, m_maxDt);
		if (r == std::string::npos) continue;
		cand.emplace_back(
			std::abs(reference.poses[r].t - estimate.poses[e].t), r, e);
	}
	std::sort(cand.begin(), cand.end());
	std::vector<bool> usedRef(reference.poses.size(), false);
	std::vector<std::pair<size_t, size_t>> pairs;
	for (const auto& [dt, r, e] : cand)
	{
		if (usedRef[r]) continue;
		usedRef[r] = true;
		pairs.emplace_back(r, e);
	}
	std::sort(pairs.begin(), pairs.end(), [](const auto& a, const auto& b) {
		return a.second < b.second;
	});
	return pairs;
}

EvaluationReport TrajectoryEvaluator::evaluate(
	const Trajectory& reference, const Trajectory& estimate) const
{
	EvaluationReport rep;
	rep.reference = reference.source;
	rep.estimate = estimate.source;
	rep.maxTimeDifference = m_maxDt;
	rep.pairedByIndex = !reference.timed || !estimate.timed;
	rep.hasTrajectoryMetrics = true;
	rep.referencePoses = reference.poses.size();
	rep.estimatePoses = estimate.poses.size();
	const auto pairs = associate(reference, estimate);
	rep.associated = pairs.size();
	if (pairs.size() < 2)
		throw InputError(
			"only " + std::to_string(pairs.size()) + " of the " +
			std::to_string(estimate.poses.size()) + " poses of '" +
			estimate.source + "' have a reference pose in '" +
			reference.source + "' within " + std::to_string(m_maxDt) +
			" s; are both in the same time base?");

	// Alignment: centre both point sets in double precision first, since
	// TMatchingPair stores floats.
	double rx = 0, ry = 0, ex = 0, ey = 0;
	for (const auto& [r, e] : pairs)
	{
		rx += reference.poses[r].pose.x;
		ry += reference.poses[r].pose.y;
		ex += estimate.poses[e].pose.x;
		ey += estimate.poses[e].pose.y;
	}
	const double n = static_cast<double>(pairs.size());
	rx /= n;
	ry /= n;
	ex /= n;
	ey /= n;
	mrpt::tfest::TMatchingPairList corrs;
	for (const auto& [r, e] : pairs)
	{
		const auto& rp = reference.poses[r].pose;
		const auto& ep = estimate.poses[e].pose;
		corrs.emplace_back(
			static_cast<uint32_t>(r), static_cast<uint32_t>(e),
			static_cast<float>(rp.x - rx), static_cast<float>(rp.y - ry), 0.0f,
			static_cast<float>(ep.x - ex), static_cast<float>(ep.y - ey), 0.0f);
	}
	rep.aligned = m_align;
	if (m_align)
	{
		mrpt::math::TPose2D centred;
		mrpt::tfest::se2_l2(corrs, centred);
		// ref - rc = R (est - ec) + t  =>  ref = R est + (t + rc - R ec)
		const double c = std::cos(centred.phi), s = std::sin(centred.phi);
		rep.alignment = {
			centred.x + rx - (c * ex - s * ey), centred.y + ry - (s * ex + c * ey),
			centred.phi};
	}
	const CPose2D align(rep.alignment);

	std::vector<double> pos, rot, rpeT, rpeR;
	for (size_t k = 0; k < pairs.size(); k++)
	{
		const auto& [r, e] = pairs[k];
		const CPose2D ref = asPose(reference.poses[r]);
		const CPose2D est = align + asPose(estimate.poses[e]);
		pos.push_back(std::hypot(ref.x() - est.x(), ref.y() - est.y()));
		rot.push_back(std::abs(mrpt::math::wrapToPi(ref.phi() - est.phi())));
		if (k == 0) continue;
		const auto& [r0, e0] = pairs[k - 1];
		const auto [et, er] = relativeError(
			asPose(reference.poses[r]) - asPose(reference.poses[r0]),
			asPose(estimate.poses[e]) - asPose(estimate.poses[e0]));
		rpeT.push_back(et);
		rpeR.push_back(er);
		rep.rpeSteps.push_back({r0, r, et, er});
	}
	rep.ate = ErrorStats::of(pos);
	rep.ateRotation = ErrorStats::of(rot);
	rep.rpeTranslation = ErrorStats::of(rpeT);
	rep.rpeRotation = ErrorStats::of(rpeR);
	neesOf(reference, estimate, pairs, rep);
	return rep;
}

void TrajectoryEvaluator::neesOf(
	const Trajectory& reference, const Trajectory& estimate,
	const std::vector<std::pair<size_t, size_t>>& pairs, EvaluationReport& rep) const
{
	// The estimator's covariance grows from its first pose, so the estimate
	// is anchored there (moved so that its first associated pose is the
	// reference's), not least-squares aligned: the alignment would absorb
	// part of the very error the covariance describes.
	const auto& [r0, e0] = pairs.front();
	const CPose2D anchor = asPose(reference.poses[r0]) - asPose(estimate.poses[e0]);
	const double c = std::cos(anchor.phi()), s = std::sin(anchor.phi());
	Eigen::Matrix3d rot = Eigen::Matrix3d::Identity();
	rot.block<2, 2>(0, 0) << c, -s, s, c;
	std::vector<double> nees;
	size_t within = 0;
	for (size_t k = 1; k < pairs.size(); k++)
	{
		const auto& [r, e] = pairs[k];
		const TimedPose& est = estimate.poses[e];
		if (!est.hasCovariance) continue;
		const Eigen::Matrix3d P = rot * est.cov.asEigen() * rot.transpose();
		const Eigen::LDLT<Eigen::Matrix3d> ldlt(P);
		if (ldlt.info() != Eigen::Success || !(P.determinant() > 0)) continue;
		const CPose2D ref = asPose(reference.poses[r]), moved = anchor + asPose(est);
		const Eigen::Vector3d d = poseDifference(ref, moved);
		nees.push_back(d.dot(ldlt.solve(d)));
		rep.neesSeries.emplace_back(est.t, nees.back());
		if (nees.back() <= EvaluationReport::kNeesBound95) within++;
	}
	if (nees.empty()) return;
	rep.hasNees = true;
	rep.nees = ErrorStats::of(nees);
	rep.neesWithin95 = static_cast<double>(within) / static_cast<double>(nees.size());
}

EvaluationReport TrajectoryEvaluator::evaluateRelations(
	const std::vector<PoseRelation>& relations, const Trajectory& estimate) const
{
	EvaluationReport rep;
	rep.estimate = estimate.source;
	rep.maxTimeDifference = m_maxDt;
	rep.hasRelations = true;
	rep.relations = relations.size();
	std::vector<double> trans, rot;
	for (const auto& rel : relations)
	{
		const size_t a = nearest(estimate, rel.t1, m_maxDt);
		const size_t b = nearest(estimate, rel.t2, m_maxDt);
		if (a == std::string::npos || b == std::string::npos) continue;
		const auto [et, er] = relativeError(
			CPose2D(rel.delta),
			asPose(estimate.poses[b]) - asPose(estimate.poses[a]));
		trans.push_back(et);
		rot.push_back(er);
	}
	rep.relationsMatched = trans.size();
	if (trans.empty())
		throw InputError(
			"none of the " + std::to_string(relations.size()) +
			" relations has estimated poses within " +
			std::to_string(m_maxDt) + " s of both its times in '" +
			estimate.source + "'");
	rep.relationTranslation = ErrorStats::of(trans);
	rep.relationRotation = ErrorStats::of(rot);
	return rep;
}
}  // namespace featloc
