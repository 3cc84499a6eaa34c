// EkfLocalizer, continued: the vertical-line landmarks of Moon, Miura &
// Shirai (1999), section 5 (kept apart from the point landmarks' file).
#include <mrpt/math/distributions.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

#include "featloc/ekf/EkfLocalizer.h"
#include "featloc/ekf/VerticalLandmarkConstraint.h"

namespace featloc
{
namespace
{
/** Least variance across the wall given to a new landmark: eq. (17) is
 * rank 1 (sigma_y = 0 in the paper's Table 1); this keeps the covariance
 * numerically positive definite without moving it off the wall [m^2]. */
constexpr double kAcrossWallVariance = 1e-6;
/** Variance of an end height not observed when the landmark starts
 * (its segment reached the image border) [m^2]. */
constexpr double kUnobservedEndVariance = 1.0;
}  // namespace

double EkfLocalizer::verticalDistance2(const Belief& b, const VerticalLandmarkObservation& z, size_t j) const
{
	const VerticalLandmarkConstraint g(z);
	const Eigen::Index k = m_info[j].index;
	Eigen::MatrixXd GX, Gl;
	const Eigen::VectorXd nu = -g.evaluate(b.x.segment<3>(kRobot), b.x.segment<4>(k), &GX, &Gl);
	const std::vector<Eigen::Index> idx{kRobot, kRobot + 1, kRobot + 2, k, k + 1, k + 2, k + 3};
	Eigen::MatrixXd H(g.size(), 7);
	H << GX, Gl;
	const Eigen::MatrixXd S = H * b.P(idx, idx) * H.transpose() + g.noise();
	return nu.dot(S.ldlt().solve(nu));
}

double EkfLocalizer::wallDistance2(
	const Belief& b, const StereoWallObservation& w, Eigen::Vector2d* nu, Eigen::Matrix<double, 2, 3>* H) const
{
	Eigen::Matrix<double, 2, 3> Hw;
	const Eigen::Vector2d r = w.line - w.predict(b.x.segment<3>(kRobot), &Hw);
	const Eigen::Matrix2d S = Hw * b.P.block<3, 3>(kRobot, kRobot) * Hw.transpose() + w.covariance;
	if (nu) *nu = r;
	if (H) *H = Hw;
	return r.dot(S.ldlt().solve(r));
}

EkfLocalizer::VerticalStack EkfLocalizer::stackVertical(const Belief& b,
	const std::vector<VerticalLandmarkObservation>& obs, const std::vector<int>& pairing,
	const std::vector<std::pair<double, size_t>>& paired,
	const std::vector<const StereoWallObservation*>& wallsUsed) const
{
	// An observed end enters the update only where it agrees with the
	// landmark's (1 dof gate): a shorter piece of the line moves neither.
	const double endGate2 = mrpt::math::chi2inv(options.landmark_gate_probability, 1);
	std::vector<VerticalLandmarkObservation> used;
	std::vector<Eigen::Index> firstRow;	 // of each used observation in the stack
	Eigen::Index m = 0;
	for (const auto& pr : paired)
	{
		VerticalLandmarkObservation z = obs[pr.second];
		const Eigen::Index k = m_info[static_cast<size_t>(pairing[pr.second])].index;
		auto check = [&](double measured, double& sigma, Eigen::Index e) {
			const double d = measured - b.x[e];
			if (sigma > 0 && d * d > endGate2 * (sigma * sigma + b.P(e, e))) sigma = 0;
		};
		check(z.lLow, z.sigmaLow, k + 2);
		check(z.lHigh, z.sigmaHigh, k + 3);
		used.push_back(z);
		firstRow.push_back(m);
		m += VerticalLandmarkConstraint(z).size();
	}
	// Stacked constraint on [robot; landmarks used]: nu = -G, H = dG/dS.
	VerticalStack st;
	st.cols = {kRobot, kRobot + 1, kRobot + 2};
	m += 2 * static_cast<Eigen::Index>(wallsUsed.size());
	st.H = Eigen::MatrixXd::Zero(m, 3 + 4 * static_cast<Eigen::Index>(paired.size()));
	st.nu.resize(m);
	st.R = Eigen::MatrixXd::Zero(m, m);
	Eigen::Index row = 0, col = 3;
	for (size_t a = 0; a < paired.size(); a++)
	{
		const size_t j = static_cast<size_t>(pairing[paired[a].second]);
		const VerticalLandmarkConstraint g(used[a]);
		const Eigen::Index k = m_info[j].index, r = g.size();
		Eigen::MatrixXd GX, Gl;
		st.nu.segment(row, r) = -g.evaluate(b.x.segment<3>(kRobot), b.x.segment<4>(k), &GX, &Gl);
		st.H.block(row, 0, r, 3) = GX;
		st.H.block(row, col, r, 4) = Gl;
		st.R.block(row, row, r, r) = g.noise();
		for (Eigen::Index c = 0; c < 4; c++) st.cols.push_back(k + c);
		// The observations of one wall share its plane fit: their
		// positions' (rows 0-1) cross-covariance.
		for (size_t b2 = 0; b2 < a; b2++)
		{
			const auto& zb = used[b2];
			if (zb.wall != used[a].wall) continue;
			const Eigen::Matrix2d C =
				used[a].planeJacobian * used[a].planeCovariance * zb.planeJacobian.transpose();
			st.R.block<2, 2>(row, firstRow[b2]) = C;
			st.R.block<2, 2>(firstRow[b2], row) = C.transpose();
		}
		row += r;
		col += 4;
	}
	// The walls: nu = z - h(X), H = dh/dX on the robot. The observations
	// on a wall were constrained to its fit over all its pixels (3.1):
	// position_i's error is planeJacobian_i times that fit's. The wall's
	// own fit uses a subset of the same pixels (its visible columns), and a
	// least-squares fit's covariance with a fit to a subset of its data is
	// its own: Cov(position_i, wall fit) = planeJacobian_i planeCovariance.
	for (const StereoWallObservation* w : wallsUsed)
	{
		Eigen::Vector2d nu;
		Eigen::Matrix<double, 2, 3> Hw;
		wallDistance2(b, *w, &nu, &Hw);
		st.nu.segment<2>(row) = nu;
		st.H.block<2, 3>(row, 0) = Hw;
		st.R.block<2, 2>(row, row) = w->covariance;
		for (size_t a = 0; a < used.size(); a++)
		{
			if (used[a].wall != w->wall) continue;
			const Eigen::Matrix2d C = used[a].planeJacobian * used[a].planeCovariance;
			st.R.block<2, 2>(firstRow[a], row) = C;
			st.R.block<2, 2>(row, firstRow[a]) = C.transpose();
		}
		row += 2;
	}
	return st;
}

EkfLocalizer::VerticalUpdate EkfLocalizer::updateVerticalLandmarks(
	const std::vector<VerticalLandmarkObservation>& obs, const std::vector<StereoWallObservation>& walls)
{
	m_verticalFrames++;
	pruneLandmarks(true);
	const Belief b = belief();
	VerticalUpdate out;
	out.observed = obs.size();
	out.landmarkOf.assign(obs.size(), -1);
	const double p = options.landmark_gate_probability;
	const size_t L = m_info.size();

	// Candidates: same wall, same polarity, overlapping heights, position
	// inside the gate (2 dof). The ends do not decide: a segment broken by
	// an occluder or a weak stretch of edge is still the same line.
	std::vector<std::tuple<double, size_t, size_t>> all;  // (d2, observation, landmark)
	const double gate2 = mrpt::math::chi2inv(p, 2);
	const double newGate2 = mrpt::math::chi2inv(options.landmark_new_probability, 2);
	auto positionDistance2 = [&](const VerticalLandmarkObservation& z, size_t j) {
		const auto& info = m_info[j];
		if (!info.vertical() || info.wall != z.wall || info.polarity != z.polarity)
			return std::numeric_limits<double>::infinity();
		const Eigen::Index k = info.index;
		if (z.lHigh < b.x[k + 2] || z.lLow > b.x[k + 3]) return std::numeric_limits<double>::infinity();
		VerticalLandmarkObservation position = z;
		position.sigmaLow = position.sigmaHigh = 0;
		return verticalDistance2(b, position, j);
	};
	for (size_t i = 0; i < obs.size(); i++)
		for (size_t j = 0; j < L; j++)
		{
			const double d2 = positionDistance2(obs[i], j);
			if (d2 <= gate2) all.emplace_back(d2, i, j);
		}
	// Nearest neighbour, the most certain pairs first, each landmark once.
	std::sort(all.begin(), all.end());
	std::vector<int> pairing(obs.size(), -1);
	std::vector<char> taken(L, 0);
	for (const auto& [d2, i, j] : all)
		if (pairing[i] < 0 && !taken[j])
		{
			pairing[i] = static_cast<int>(j);
			taken[j] = 1;
		}
	// The least uncertain landmarks (trace of their position covariance).
	std::vector<std::pair<double, size_t>> paired;
	for (size_t i = 0; i < obs.size(); i++)
		if (pairing[i] >= 0)
		{
			const Eigen::Index k = m_info[static_cast<size_t>(pairing[i])].index;
			paired.emplace_back(b.P(k, k) + b.P(k + 1, k + 1), i);
		}
	out.associated = paired.size();
	std::sort(paired.begin(), paired.end());
	if (paired.size() > options.stereo_landmarks_per_frame) paired.resize(options.stereo_landmarks_per_frame);

	// Each fitted wall against the map, alone (2 dof).
	out.wallsObserved = walls.size();
	out.wallMahalanobis2.resize(walls.size());
	out.wallOutcome.assign(walls.size(), "dropped by the joint gate");
	std::vector<const StereoWallObservation*> wallsUsed;
	for (size_t i = 0; i < walls.size(); i++)
	{
		out.wallMahalanobis2[i] = wallDistance2(b, walls[i]);
		if (out.wallMahalanobis2[i] <= gate2)
			wallsUsed.push_back(&walls[i]);
		else
		{
			out.wallsRejected++;
			out.wallOutcome[i] = "failed its gate";
		}
	}

	// The pairs and walls used must be jointly compatible (chi-square, all
	// their rows): while they are not, the one farthest from its
	// prediction is dropped. Individually plausible pairs can still share
	// one wrong cause (a landmark started from a misplaced boundary).
	VerticalStack joint;  // of the pairs left: the update's terms
	while (!paired.empty() || !wallsUsed.empty())
	{
		joint = stackVertical(b, obs, pairing, paired, wallsUsed);
		const double limit = mrpt::math::chi2inv(p, static_cast<unsigned>(joint.nu.size()));
		const double d2 = joint.nu.dot(
			(joint.H * b.P(joint.cols, joint.cols) * joint.H.transpose() + joint.R).ldlt().solve(joint.nu));
		if (d2 <= limit) break;
		size_t worst = 0;
		double worstD2 = -1;
		for (size_t a = 0; a < paired.size() + wallsUsed.size(); a++)
		{
			const double da = a < paired.size()
				? verticalDistance2(b, obs[paired[a].second], static_cast<size_t>(pairing[paired[a].second]))
				: out.wallMahalanobis2[static_cast<size_t>(wallsUsed[a - paired.size()] - walls.data())];
			if (da > worstD2) worstD2 = da, worst = a;
		}
		if (worst < paired.size())
		{
			pairing[paired[worst].second] = -1;
			paired.erase(paired.begin() + static_cast<long>(worst));
			out.inconsistent++;
		}
		else
			wallsUsed.erase(wallsUsed.begin() + static_cast<long>(worst - paired.size()));
	}
	out.wallsUsed = wallsUsed.size();
	for (const StereoWallObservation* w : wallsUsed) out.wallOutcome[static_cast<size_t>(w - walls.data())] = "used";
	if (!paired.empty() || !wallsUsed.empty())
	{
		out.jointMahalanobis2 = updateAtBelief(b, joint.cols, joint.H, joint.nu, joint.R);
		for (const auto& pr : paired)
		{
			const size_t j = static_cast<size_t>(pairing[pr.second]);
			m_info[j].observations++;
			out.landmarkOf[pr.second] = static_cast<int>(j);
		}
		out.used = paired.size();
	}
	// Landmarks started on-line (section 5): selected features compatible
	// with no landmark of their wall.
	const size_t firstNew = m_info.size();
	std::vector<size_t> started;
	for (size_t i = 0; i < obs.size(); i++)
	{
		if (pairing[i] >= 0 || !obs[i].canStart) continue;
		// Near a landmark: ambiguous, not new. Against this frame's new
		// ones the start positions are compared (both relative to the map,
		// the robot's uncertainty not in between): two pieces of one line
		// start one landmark, two lines of one frame two.
		bool nearSome = false;
		for (size_t j = 0; j < firstNew && !nearSome; j++)
			nearSome = positionDistance2(obs[i], j) <= newGate2;
		for (const size_t a : started)
		{
			const auto& o = obs[a];
			if (nearSome || o.wall != obs[i].wall || o.polarity != obs[i].polarity ||
				o.lHigh < obs[i].lLow || o.lLow > obs[i].lHigh)
				continue;
			// Their common boundary error cancels in the difference.
			const Eigen::Vector2d d = o.start - obs[i].start;
			const double var =
				(o.startCovariance + obs[i].startCovariance - 2 * o.startSharedCovariance).trace() +
				2 * kAcrossWallVariance;
			nearSome = d.squaredNorm() <= mrpt::math::chi2inv(options.landmark_new_probability, 1) * var;
		}
		if (nearSome)
		{
			out.ambiguous++;
			continue;
		}
		const auto& z = obs[i];
		Eigen::Vector4d mean(z.start.x(), z.start.y(), z.lLow, z.lHigh);
		Eigen::Matrix4d cov = Eigen::Matrix4d::Zero();
		cov.block<2, 2>(0, 0) = z.startCovariance;
		// Across the wall: the eq. (17) covariance's null direction.
		const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(z.startCovariance);
		const Eigen::Vector2d across = es.eigenvectors().col(0);
		cov.block<2, 2>(0, 0) += kAcrossWallVariance * across * across.transpose();
		cov(2, 2) = z.sigmaLow > 0 ? z.sigmaLow * z.sigmaLow : kUnobservedEndVariance;
		cov(3, 3) = z.sigmaHigh > 0 ? z.sigmaHigh * z.sigmaHigh : kUnobservedEndVariance;
		LandmarkInfo info;
		info.observations = 1;
		info.firstFrame = m_verticalFrames;
		info.wall = z.wall;
		info.polarity = z.polarity;
		// Relative to the map's edge: uncorrelated with the robot (eq. 17).
		// Correlated with the landmarks started from the same boundary in
		// this frame (same wall) by that boundary's error: without it, N of
		// them would make the robot believe the boundary known sqrt(N)
		// times better than it is.
		Eigen::MatrixXd cross = Eigen::MatrixXd::Zero(4, m_x.size());
		for (size_t a = 0; a < started.size(); a++)
			if (obs[started[a]].wall == z.wall)
				cross.block<2, 2>(0, m_info[firstNew + a].index) = z.startSharedCovariance;
		appendLandmark(mean, cov, cross, info);
		out.landmarkOf[i] = static_cast<int>(m_info.size() - 1);
		out.added++;
		started.push_back(i);
	}
	return out;
}
}  // namespace featloc
