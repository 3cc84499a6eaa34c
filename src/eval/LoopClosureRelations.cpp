#include "featloc/eval/LoopClosureRelations.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>

#include "featloc/core/InputError.h"
#include "featloc/core/WholeFile.h"
#include "featloc/eval/TrajectoryEvaluator.h"
#include "featloc/math/PoseDifference.h"

namespace featloc
{
LoopClosureRelations::Result LoopClosureRelations::find(
	const std::vector<mrpt::obs::CObservation2DRangeScan::Ptr>& scans,
	const std::vector<double>& times, const Trajectory& trajectory, ScanMatcher& matcher,
	const Options& o)
{
	// The trajectory's pose of every scan (within 1 ms of its time).
	Trajectory at;
	for (double t : times)
	{
		TimedPose p;
		p.t = t;
		at.poses.push_back(p);
	}
	std::vector<bool> known(scans.size(), false);
	std::vector<mrpt::poses::CPose2D> pose(scans.size());
	for (const auto& [g, s] : TrajectoryEvaluator(0.001).associate(trajectory, at))
	{
		known[s] = true;
		pose[s] = mrpt::poses::CPose2D(trajectory.poses[g].pose);
	}
	Result r;
	for (size_t i = 0; i < scans.size(); i += std::max<size_t>(1, o.stride))
	{
		if (!known[i]) continue;
		size_t best = scans.size();
		double bestDistance = o.max_distance;
		for (size_t j = i + o.min_gap; j < scans.size(); j++)
		{
			if (!known[j]) continue;
			const mrpt::poses::CPose2D d = pose[j] - pose[i];
			if (std::abs(d.phi()) > o.max_angle) continue;
			if (d.norm() <= bestDistance)
			{
				bestDistance = d.norm();
				best = j;
			}
		}
		if (best == scans.size()) continue;
		r.revisits++;
		mrpt::poses::CPosePDFGaussian guess;
		guess.mean = pose[best] - pose[i];
		guess.cov.setZero();
		guess.cov(0, 0) = guess.cov(1, 1) = o.guess_sigma_xy * o.guess_sigma_xy;
		guess.cov(2, 2) = o.guess_sigma_yaw * o.guess_sigma_yaw;
		const MatchResult m = matcher.match(*scans[i], *scans[best], guess);
		if (!m.success || m.ambiguous)
		{
			r.failed++;
			const std::string kind = m.success ? "ambiguous" : m.failureKind;
			r.failuresByKind[kind]++;
			r.exampleByKind.emplace(kind, m.success ? m.ambiguityReason : m.failureReason);
			continue;
		}
		r.relations.push_back({times[i], times[best], m.estimate.mean.asTPose()});
	}
	return r;
}

void LoopClosureRelations::write(
	const std::string& path, const std::vector<PoseRelation>& relations, const std::string& comment)
{
	writeWholeFile(path, [&](const std::string& file) {
		std::ofstream out(file);
		if (!out) throw std::runtime_error("cannot write '" + path + "'");
		out << "# " << comment << "\n# t1 t2 x y z roll pitch yaw (pose at t2 in the frame of t1)\n";
		char row[192];
		for (const auto& rel : relations)
		{
			std::snprintf(row, sizeof(row), "%.9f %.9f %.6f %.6f 0 0 0 %.8f\n", rel.t1, rel.t2,
				rel.delta.x, rel.delta.y, rel.delta.phi);
			out << row;
		}
		out.close();
		if (!out) throw std::runtime_error("error writing '" + path + "'");
	});
}
}  // namespace featloc
