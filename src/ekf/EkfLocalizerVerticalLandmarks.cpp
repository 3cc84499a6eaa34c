// EkfLocalizer, continued: the vertical-line landmarks of Moon, Miura &
// Shirai (1999), section 5 (kept apart from the point landmarks' file).
#include <mrpt/math/distributions.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
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

double EkfLocalizer::verticalDistance2(const VerticalLandmarkObservation& z, size_t j) const
{
	const VerticalLandmarkConstraint g(z);
	const Eigen::Index k = m_info[j].index;
	Eigen::MatrixXd GX, Gl;
	const Eigen::VectorXd nu = -g.evaluate(m_x.segment<3>(kRobot), m_x.segment<4>(k), &GX, &Gl);
	const std::vector<Eigen::Index> idx{kRobot, kRobot + 1, kRobot + 2, k, k + 1, k + 2, k + 3};
	Eigen::MatrixXd H(g.size(), 7);
	H << GX, Gl;
	const Eigen::MatrixXd S = H * P()(idx, idx) * H.transpose() + g.noise();
	return nu.dot(S.ldlt().solve(nu));
}

EkfLocalizer::VerticalUpdate EkfLocalizer::updateVerticalLandmarks(
	const std::vector<VerticalLandmarkObservation>& obs)
{
	VerticalUpdate out;
	out.observed = obs.size();
	out.landmarkOf.assign(obs.size(), -1);
	const double p = options.landmark_gate_probability;
	const size_t L = m_info.size();

	// Candidates: same wall, same polarity, inside the gate (its dof: 2
	// for the position, one per observed end).
	std::vector<std::tuple<double, size_t, size_t>> all;  // (d2, observation, landmark)
	std::vector<char> nearSome(obs.size(), 0);
	for (size_t i = 0; i < obs.size(); i++)
	{
		const auto dof = static_cast<unsigned>(VerticalLandmarkConstraint(obs[i]).size());
		const double gate2 = mrpt::math::chi2inv(p, dof);
		const double newGate2 = mrpt::math::chi2inv(options.landmark_new_probability, dof);
		for (size_t j = 0; j < L; j++)
		{
			const auto& info = m_info[j];
			if (!info.vertical() || info.wall != obs[i].wall || info.polarity != obs[i].polarity) continue;
			const double d2 = verticalDistance2(obs[i], j);
			if (d2 <= gate2) all.emplace_back(d2, i, j);
			if (d2 <= newGate2) nearSome[i] = 1;
		}
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
			paired.emplace_back(P()(k, k) + P()(k + 1, k + 1), i);
		}
	out.associated = paired.size();
	std::sort(paired.begin(), paired.end());
	if (paired.size() > options.stereo_landmarks_per_frame) paired.resize(options.stereo_landmarks_per_frame);

	if (!paired.empty())
	{
		// Stacked constraint on [robot; landmarks used]: nu = -G, H = dG/dS.
		Eigen::Index m = 0;
		for (const auto& pr : paired) m += VerticalLandmarkConstraint(obs[pr.second]).size();
		std::vector<Eigen::Index> cols{kRobot, kRobot + 1, kRobot + 2};
		Eigen::MatrixXd H = Eigen::MatrixXd::Zero(m, 3 + 4 * static_cast<Eigen::Index>(paired.size()));
		Eigen::VectorXd nu(m);
		Eigen::MatrixXd R = Eigen::MatrixXd::Zero(m, m);
		Eigen::Index row = 0, col = 3;
		for (const auto& pr : paired)
		{
			const size_t i = pr.second, j = static_cast<size_t>(pairing[i]);
			const VerticalLandmarkConstraint g(obs[i]);
			const Eigen::Index k = m_info[j].index, r = g.size();
			Eigen::MatrixXd GX, Gl;
			nu.segment(row, r) = -g.evaluate(m_x.segment<3>(kRobot), m_x.segment<4>(k), &GX, &Gl);
			H.block(row, 0, r, 3) = GX;
			H.block(row, col, r, 4) = Gl;
			R.block(row, row, r, r) = g.noise();
			for (Eigen::Index c = 0; c < 4; c++) cols.push_back(k + c);
			row += r;
			col += 4;
		}
		out.jointMahalanobis2 = update(cols, H, nu, R);
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
	for (size_t i = 0; i < obs.size(); i++)
	{
		if (pairing[i] >= 0 || !obs[i].canStart) continue;
		if (nearSome[i])
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
		info.firstStep = m_step;
		info.wall = z.wall;
		info.polarity = z.polarity;
		// Relative to the map's edge: uncorrelated with the robot (eq. 17).
		appendLandmark(mean, cov, Eigen::MatrixXd::Zero(4, m_x.size()), info);
		out.landmarkOf[i] = static_cast<int>(m_info.size() - 1);
		out.added++;
	}
	return out;
}
}  // namespace featloc
