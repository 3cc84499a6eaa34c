#include "featloc/ekf/EkfLocalizer.h"

#include <mrpt/math/distributions.h>
#include <mrpt/math/wrap2pi.h>
#include <mrpt/poses/CPosePDF.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>

#include "featloc/ekf/JointCompatibilityBranchAndBound.h"
#include "featloc/ekf/LandmarkJointInnovation.h"
#include "featloc/ekf/VerticalLandmarkConstraint.h"

namespace featloc
{
namespace
{
Eigen::Matrix2d rotation(double th)
{
	Eigen::Matrix2d R;
	R << std::cos(th), -std::sin(th), std::sin(th), std::cos(th);
	return R;
}

/** dR(th)^T/dth times d. */
Eigen::Vector2d dRtTimes(double th, const Eigen::Vector2d& d)
{
	const double c = std::cos(th), s = std::sin(th);
	return {-s * d.x() + c * d.y(), -c * d.x() - s * d.y()};
}

mrpt::poses::CPosePDFGaussian poseAt(const Eigen::VectorXd& x, const Eigen::Matrix3d& P, Eigen::Index k)
{
	const Eigen::Matrix3d sym = 0.5 * (P + P.transpose());
	return mrpt::poses::CPosePDFGaussian(
		mrpt::poses::CPose2D(x[k], x[k + 1], x[k + 2]), mrpt::math::CMatrixDouble33(sym));
}
}  // namespace

void EkfLocalizer::reset(const mrpt::poses::CPosePDFGaussian& initial)
{
	m_x = Eigen::VectorXd::Zero(kLandmarks);
	m_Pbuf = Eigen::MatrixXd::Zero(kLandmarks + 2 * 32, kLandmarks + 2 * 32);
	m_x.segment<3>(kRobot) << initial.mean.x(), initial.mean.y(), initial.mean.phi();
	P().block<3, 3>(kRobot, kRobot) = initial.cov.asEigen();
	P()(kOdometryDirection, kOdometryDirection) = mrpt::square(options.odometry_direction_sigma);
	m_info.clear();
	m_held.reset();
	m_pointFrames = m_verticalFrames = 0;
	clonePose(kClone);
	clonePose(kMatchClone);
}

void EkfLocalizer::reserve(Eigen::Index n)
{
	if (m_Pbuf.rows() >= n) return;
	// Doubling: adding a landmark copies O(n) entries, not the whole matrix.
	const Eigen::Index cap = std::max(n, 2 * m_Pbuf.rows());
	Eigen::MatrixXd grown = Eigen::MatrixXd::Zero(cap, cap);
	const Eigen::Index used = m_x.size();
	grown.topLeftCorner(used, used) = m_Pbuf.topLeftCorner(used, used);
	m_Pbuf.swap(grown);
}

void EkfLocalizer::predict(
	const mrpt::poses::CPosePDFGaussian& u, const mrpt::math::CMatrixDouble33& samplingCovariance)
{
	// x_r <- x_r (+) v, v = e (+) u_b: u_b is the odometry increment with its
	// translation turned by the direction offset b; e is the last reading's
	// error, taken back (zero, with zero covariance, while no reading had
	// one). Then the new reading's error e' is taken off: x_r (+) (-e') ~
	// x_r - G e' with G the rotation into the world (MRPT's J_u at e' = 0).
	// See the class comment.
	const Eigen::Index n = m_x.size(), E = kSamplingError, D = kOdometryDirection;
	const double b = m_x[D], cb = std::cos(b), sb = std::sin(b);
	const double ux = u.mean.x(), uy = u.mean.y();
	const mrpt::poses::CPose2D ub(cb * ux - sb * uy, sb * ux + cb * uy, u.mean.phi());
	const Eigen::Vector3d dub(-sb * ux - cb * uy, cb * ux - sb * uy, 0);  // d u_b / d b
	const mrpt::poses::CPose2D x(m_x[0], m_x[1], m_x[2]);
	const mrpt::poses::CPose2D e(m_x[E], m_x[E + 1], m_x[E + 2]);
	mrpt::math::CMatrixDouble33 Je, Jue, Jx, Ju;
	mrpt::poses::CPosePDF::jacobiansPoseComposition(e, ub, Je, Jue);
	const mrpt::poses::CPose2D v = e + ub;
	mrpt::poses::CPosePDF::jacobiansPoseComposition(x, v, Jx, Ju);
	const mrpt::poses::CPose2D next = x + v;
	m_x.segment<3>(kRobot) << next.x(), next.y(), next.phi();
	const Eigen::Matrix3d B = Ju.asEigen(), Bu = B * Jue.asEigen();
	// The new robot pose's Jacobian in what it is computed from: the old
	// pose, e and b.
	Eigen::Matrix<double, 3, 7> T;
	T << Jx.asEigen(), B * Je.asEigen(), Bu * dub;
	Eigen::Matrix3d G = Eigen::Matrix3d::Zero();
	G.topLeftCorner<2, 2>() = -rotation(next.phi());
	G(2, 2) = -1;
	const Eigen::Matrix3d Sigma = samplingCovariance.asEigen();
	auto Pn = P();
	const std::vector<Eigen::Index> from = {kRobot, kRobot + 1, kRobot + 2, E, E + 1, E + 2, D};
	const Eigen::Matrix3d Prr = T * Pn(from, from) * T.transpose() +
		Bu * u.cov.asEigen() * Bu.transpose() + G * Sigma * G.transpose();
	// The robot's correlations with the rest (e's columns are replaced
	// below).
	const Eigen::MatrixXd Prest = T * Pn(from, Eigen::seq(3, n - 1));
	Pn.block<3, 3>(kRobot, kRobot) = 0.5 * (Prr + Prr.transpose());
	Pn.block(kRobot, 3, 3, n - 3) = Prest;
	Pn.block(3, kRobot, n - 3, 3) = Prest.transpose();
	// e' is new: independent of everything but the robot pose it displaced.
	Pn.middleRows(E, 3).setZero();
	Pn.middleCols(E, 3).setZero();
	Pn.block<3, 3>(E, E) = Sigma;
	Pn.block<3, 3>(E, kRobot) = Sigma * G.transpose();
	Pn.block<3, 3>(kRobot, E) = G * Sigma;
	m_x.segment<3>(E).setZero();
}

void EkfLocalizer::clonePose(Eigen::Index to)
{
	const Eigen::Index n = m_x.size();
	m_x.segment<3>(to) = m_x.segment<3>(kRobot);
	P().block(to, 0, 3, n) = P().block(kRobot, 0, 3, n);
	P().block(0, to, n, 3) = P().block(0, kRobot, n, 3);
	P().block<3, 3>(to, to) = P().block<3, 3>(kRobot, kRobot);
}

void EkfLocalizer::cloneKeyframe()
{
	// A held match measures from the old keyframe clone: fuse it before the
	// clone is overwritten, or it would be lost.
	commitHeldMotion();
	clonePose(kClone);
}

double EkfLocalizer::update(
	const std::vector<Eigen::Index>& cols, const Eigen::MatrixXd& Hc, const Eigen::VectorXd& nu,
	const Eigen::MatrixXd& R)
{
	// H is zero outside `cols`: P H^T = P(:, cols) Hc^T, H P H^T = Hc P(cols, cols) Hc^T.
	auto Pn = P();
	const Eigen::MatrixXd PHt = Pn(Eigen::all, cols) * Hc.transpose();
	const Eigen::MatrixXd S = Hc * Pn(cols, cols) * Hc.transpose() + R;
	// S = L L^T: K nu = P H^T S^-1 nu, and K S K^T = U U^T with
	// U = P H^T L^-T, one product that is symmetric by construction (no
	// n x n symmetrising pass, which costs as much as the update).
	const Eigen::LLT<Eigen::MatrixXd> llt(S);
	const Eigen::VectorXd Sinvnu = llt.solve(nu);
	m_x += PHt * Sinvnu;
	const Eigen::MatrixXd U = llt.matrixL().solve(PHt.transpose()).transpose();
	Pn.noalias() -= U * U.transpose();
	wrapPoseAngles(m_x);
	return nu.dot(Sinvnu);
}

void EkfLocalizer::wrapPoseAngles(Eigen::VectorXd& v)
{
	for (const Eigen::Index k : {kRobot, kClone, kMatchClone}) v[k + 2] = mrpt::math::wrapToPi(v[k + 2]);
}

double EkfLocalizer::updateAtBelief(const Belief& b, const std::vector<Eigen::Index>& cols,
	const Eigen::MatrixXd& Hc, const Eigen::VectorXd& nuAtBelief, const Eigen::MatrixXd& R)
{
	Eigen::VectorXd d = b.x - m_x;
	wrapPoseAngles(d);
	update(cols, Hc, nuAtBelief + Hc * d(cols), R);
	const Eigen::MatrixXd S = Hc * b.P(cols, cols) * Hc.transpose() + R;
	return nuAtBelief.dot(S.ldlt().solve(nuAtBelief));
}

Eigen::Vector3d EkfLocalizer::predictRelativeMotion(
	Eigen::Index from, Eigen::Matrix3d* Ha, Eigen::Matrix3d* Hc) const
{
	// h = x_c^-1 (+) x_a = (R_c^T (t_a - t_c), th_a - th_c).
	const double thc = m_x[kClone + 2];
	const Eigen::Vector2d d = m_x.segment<2>(from) - m_x.segment<2>(kClone);
	const Eigen::Matrix2d Rct = rotation(thc).transpose();
	if (Ha)
	{
		Ha->setZero();
		Ha->block<2, 2>(0, 0) = Rct;
		(*Ha)(2, 2) = 1;
	}
	if (Hc)
	{
		Hc->setZero();
		Hc->block<2, 2>(0, 0) = -Rct;
		Hc->block<2, 1>(0, 2) = dRtTimes(thc, d);
		(*Hc)(2, 2) = -1;
	}
	const Eigen::Vector2d t = Rct * d;
	return {t.x(), t.y(), mrpt::math::wrapToPi(m_x[from + 2] - thc)};
}

void EkfLocalizer::relativeMotionTerms(
	Eigen::Index from, const mrpt::poses::CPosePDFGaussian& z, std::vector<Eigen::Index>& cols,
	Eigen::MatrixXd& H, Eigen::VectorXd& nu) const
{
	Eigen::Matrix3d Ha, Hc;
	const Eigen::Vector3d h = predictRelativeMotion(from, &Ha, &Hc);
	cols = {from, from + 1, from + 2, kClone, kClone + 1, kClone + 2};
	H.resize(3, 6);
	H << Ha, Hc;
	nu.resize(3);
	nu << z.mean.x() - h.x(), z.mean.y() - h.y(), mrpt::math::wrapToPi(z.mean.phi() - h.z());
}

EkfLocalizer::MotionUpdate EkfLocalizer::testRelativeMotion(const mrpt::poses::CPosePDFGaussian& z) const
{
	std::vector<Eigen::Index> cols;
	Eigen::MatrixXd H;
	Eigen::VectorXd nu;
	relativeMotionTerms(kRobot, z, cols, H, nu);
	const Eigen::MatrixXd S =
		H * P()(cols, cols) * H.transpose() + z.cov.asEigen();
	return gate(nu, S, options.matcher_gate_chi2, "the match", "matcher_gate_chi2");
}

EkfLocalizer::MotionUpdate EkfLocalizer::gate(const Eigen::VectorXd& nu, const Eigen::MatrixXd& S,
	double chi2, const char* what, const char* key)
{
	MotionUpdate out;
	out.mahalanobis2 = nu.dot(S.ldlt().solve(nu));
	out.used = out.mahalanobis2 <= chi2;
	if (!out.used)
	{
		char buf[200];
		std::snprintf(buf, sizeof(buf),
			"%s disagrees with the prediction (Mahalanobis^2 %.1f > %s %.1f: %.3f m, %.2f deg "
			"apart)",
			what, out.mahalanobis2, key, chi2, std::hypot(nu[0], nu[1]), mrpt::RAD2DEG(nu[2]));
		out.reason = buf;
	}
	return out;
}

EkfLocalizer::MotionUpdate EkfLocalizer::updateAbsolutePose(
	const mrpt::poses::CPosePDFGaussian& z, double gateChi2)
{
	// Gated against the state without the held match, as the scan matches
	// are (testRelativeMotion): both are tested against the odometry's
	// prediction, neither against the other. Against the belief, a held
	// scan match wrong along a corridor (ICP beside walking people) made
	// the map matches that would have corrected it fail the gate (office,
	// run B in the world file: max error 96 -> 145 mm). H = I: no linearization
	// point to choose.
	const std::vector<Eigen::Index> cols = {kRobot, kRobot + 1, kRobot + 2};
	const Eigen::MatrixXd H = Eigen::Matrix3d::Identity();
	Eigen::VectorXd nu(3);
	nu << z.mean.x() - m_x[kRobot], z.mean.y() - m_x[kRobot + 1],
		mrpt::math::wrapToPi(z.mean.phi() - m_x[kRobot + 2]);
	const Eigen::MatrixXd S = P()(cols, cols) + z.cov.asEigen();
	const MotionUpdate out = gate(nu, S, gateChi2, "the map match", "gate_chi2");
	if (out.used) update(cols, H, nu, z.cov.asEigen());
	return out;
}

EkfLocalizer::MotionUpdate EkfLocalizer::updateRelativeMotion(
	const mrpt::poses::CPosePDFGaussian& z)
{
	const MotionUpdate out = testRelativeMotion(z);
	if (!out.used) return out;
	std::vector<Eigen::Index> cols;
	Eigen::MatrixXd H;
	Eigen::VectorXd nu;
	relativeMotionTerms(kRobot, z, cols, H, nu);
	update(cols, H, nu, z.cov.asEigen());
	return out;
}

void EkfLocalizer::holdRelativeMotion(const mrpt::poses::CPosePDFGaussian& z)
{
	clonePose(kMatchClone);
	m_held = z;
}

void EkfLocalizer::commitHeldMotion()
{
	if (!m_held) return;
	std::vector<Eigen::Index> cols;
	Eigen::MatrixXd H;
	Eigen::VectorXd nu;
	relativeMotionTerms(kMatchClone, *m_held, cols, H, nu);
	const Eigen::MatrixXd R = m_held->cov.asEigen();
	m_held.reset();
	update(cols, H, nu, R);
}

std::optional<EkfLocalizer::HeldCorrection> EkfLocalizer::heldCorrection() const
{
	if (!m_held) return std::nullopt;
	std::vector<Eigen::Index> cols;
	Eigen::MatrixXd H;
	Eigen::VectorXd nu;
	relativeMotionTerms(kMatchClone, *m_held, cols, H, nu);
	HeldCorrection c;
	c.nu = nu;
	c.S = H * P()(cols, cols) * H.transpose() + m_held->cov.asEigen();
	const Eigen::MatrixXd PHt = P()(Eigen::all, cols) * H.transpose();
	c.K = c.S.ldlt().solve(PHt.transpose()).transpose();
	return c;
}

Eigen::Vector2d EkfLocalizer::predictObservation(
	size_t j, Eigen::Matrix<double, 2, 3>* Hr, Eigen::Matrix2d* Hl) const
{
	return predictObservation(m_x, j, Hr, Hl);
}

Eigen::Vector2d EkfLocalizer::predictObservation(
	const Eigen::VectorXd& x, size_t j, Eigen::Matrix<double, 2, 3>* Hr, Eigen::Matrix2d* Hl) const
{
	const Eigen::Index k = landmarkIndex(j);
	const double th = x[kRobot + 2];
	const Eigen::Vector2d d = x.segment<2>(k) - x.segment<2>(kRobot);
	const Eigen::Matrix2d Rt = rotation(th).transpose();
	if (Hr)
	{
		Hr->block<2, 2>(0, 0) = -Rt;
		Hr->col(2) = dRtTimes(th, d);
	}
	if (Hl) *Hl = Rt;
	return Rt * d;
}

double EkfLocalizer::individualDistance2(const Belief& b, const LandmarkObservation& o, size_t j) const
{
	Eigen::Matrix<double, 2, 3> Hr;
	Eigen::Matrix2d Hl;
	const Eigen::Vector2d nu = o.position - predictObservation(b.x, j, &Hr, &Hl);
	const Eigen::Index k = landmarkIndex(j);
	const std::array<Eigen::Index, 5> idx{kRobot, kRobot + 1, kRobot + 2, k, k + 1};
	Eigen::Matrix<double, 2, 5> H;
	H << Hr, Hl;
	const Eigen::Matrix2d S = H * b.P(idx, idx) * H.transpose() + o.covariance;
	return nu.dot(S.ldlt().solve(nu));
}

EkfLocalizer::LandmarkUpdate EkfLocalizer::updateLandmarks(
	const std::vector<LandmarkObservation>& obs)
{
	m_pointFrames++;
	pruneLandmarks(false);
	const Belief b = belief();
	LandmarkUpdate out;
	out.observed = obs.size();
	const size_t n = obs.size(), L = m_info.size();
	const double p = options.landmark_gate_probability;
	const double gate2 = mrpt::math::chi2inv(p, 2);
	// An observation starts a landmark only if it is implausible for every
	// known one at this much stricter level: at gate2 alone, 1% of the
	// observations of known landmarks would each start a duplicate.
	const double newGate2 = mrpt::math::chi2inv(options.landmark_new_probability, 2);

	// Pairs: known identities directly (when plausible); the others by
	// individual gating, then joint compatibility (or nearest neighbour).
	std::vector<int> pairing(n, -1);
	std::vector<std::vector<std::pair<double, size_t>>> scored(n);
	std::vector<char> unknown(n, 0);
	std::vector<char> nearSome(n, 0);  //!< within newGate2 of some landmark
	std::vector<char> knownRejected(n, 0);	//!< known identity, failed its gate
	std::vector<std::pair<size_t, size_t>> knownPairs;
	for (size_t i = 0; i < n; i++)
	{
		if (obs[i].id >= 0)
		{
			for (size_t j = 0; j < L; j++)
				if (!m_info[j].vertical() && m_info[j].id == obs[i].id)
				{
					if (individualDistance2(b, obs[i], j) <= gate2)
					{
						pairing[i] = static_cast<int>(j);
						knownPairs.emplace_back(i, j);
					}
					else
					{
						// Known but implausible: neither fused nor a new landmark,
						// and out of every association search.
						knownRejected[i] = 1;
						out.rejected++;
					}
				}
			continue;
		}
		unknown[i] = 1;
		for (size_t j = 0; j < L; j++)
		{
			if (m_info[j].id >= 0 || m_info[j].vertical()) continue;  // identified landmarks pair by id only
			const double d2 = individualDistance2(b, obs[i], j);
			if (d2 <= gate2) scored[i].emplace_back(d2, j);
			if (d2 <= newGate2) nearSome[i] = 1;
		}
		std::sort(scored[i].begin(), scored[i].end());
	}
	std::vector<std::vector<size_t>> candidates(n);
	for (size_t i = 0; i < n; i++)
		for (const auto& [d2, j] : scored[i]) candidates[i].push_back(j);

	if (options.data_association == "jcbb")
	{
		// The known identities are the base every hypothesis extends.
		LandmarkJointInnovation joint(*this, b, obs);
		for (const auto& [i, j] : knownPairs) joint.push(i, j);
		const auto best = JointCompatibilityBranchAndBound::solve(
			candidates, joint,
			[&](size_t k) { return mrpt::math::chi2inv(p, static_cast<unsigned>(2 * k)); });
		for (size_t i = 0; i < n; i++)
			if (unknown[i]) pairing[i] = best[i];
	}
	else
	{
		// Nearest neighbour, the most certain pairs first, each landmark once.
		std::vector<std::tuple<double, size_t, size_t>> all;
		for (size_t i = 0; i < n; i++)
			for (const auto& [d2, j] : scored[i]) all.emplace_back(d2, i, j);
		std::sort(all.begin(), all.end());
		std::vector<char> used(L, 0);
		for (const auto& [d2, i, j] : all)
			if (pairing[i] < 0 && !used[j])
			{
				pairing[i] = static_cast<int>(j);
				used[j] = 1;
			}
	}

	std::vector<std::pair<size_t, size_t>> pairs;
	for (size_t i = 0; i < n; i++)
		if (pairing[i] >= 0) pairs.emplace_back(i, static_cast<size_t>(pairing[i]));
	if (!pairs.empty())
	{
		// H on [robot; landmark of pair 1; ...]: 2 rows per pair.
		const Eigen::Index m = 2 * static_cast<Eigen::Index>(pairs.size());
		std::vector<Eigen::Index> cols{kRobot, kRobot + 1, kRobot + 2};
		Eigen::MatrixXd H = Eigen::MatrixXd::Zero(m, 3 + m);
		Eigen::VectorXd nu(m);
		Eigen::MatrixXd R = Eigen::MatrixXd::Zero(m, m);
		for (size_t a = 0; a < pairs.size(); a++)
		{
			const auto [i, j] = pairs[a];
			Eigen::Matrix<double, 2, 3> Hr;
			Eigen::Matrix2d Hl;
			const Eigen::Vector2d h = predictObservation(b.x, j, &Hr, &Hl);
			const Eigen::Index row = 2 * static_cast<Eigen::Index>(a);
			H.block<2, 3>(row, 0) = Hr;
			H.block<2, 2>(row, 3 + row) = Hl;
			cols.push_back(landmarkIndex(j));
			cols.push_back(landmarkIndex(j) + 1);
			nu.segment<2>(row) = obs[i].position - h;
			R.block<2, 2>(row, row) = obs[i].covariance;
		}
		out.jointMahalanobis2 = updateAtBelief(b, cols, H, nu, R);
		for (const auto& [i, j] : pairs) m_info[j].observations++;
		out.associated = pairs.size();
	}
	// New landmarks: compatible with nothing (or a new identity).
	for (size_t i = 0; i < n; i++)
	{
		if (pairing[i] >= 0) continue;
		if (knownRejected[i]) continue;
		if (!candidates[i].empty() || nearSome[i])
		{
			if (unknown[i]) out.ambiguous++;
			continue;
		}
		addLandmark(obs[i]);
		out.added++;
	}
	return out;
}

void EkfLocalizer::addLandmark(const LandmarkObservation& o)
{
	// Inverse observation model l = t_r + R(th) z, with
	// G_r = dl/dx_r = [I, dR/dth z], G_z = R(th).
	const double th = m_x[kRobot + 2], c = std::cos(th), s = std::sin(th);
	const Eigen::Matrix2d Rr = rotation(th);
	const Eigen::Vector2d l = m_x.segment<2>(kRobot) + Rr * o.position;
	Eigen::Matrix<double, 2, 3> Gr;
	Gr.block<2, 2>(0, 0).setIdentity();
	Gr.col(2) << -s * o.position.x() - c * o.position.y(), c * o.position.x() - s * o.position.y();
	const Eigen::Index n = m_x.size();
	const Eigen::Matrix2d Pll = Gr * P().block<3, 3>(kRobot, kRobot) * Gr.transpose() +
		Rr * o.covariance * Rr.transpose();
	LandmarkInfo info;
	info.id = o.id;
	info.observations = 1;
	info.firstFrame = m_pointFrames;
	appendLandmark(l, Pll, Gr * P().block(kRobot, 0, 3, n), info);
}

void EkfLocalizer::appendLandmark(
	const Eigen::VectorXd& mean, const Eigen::MatrixXd& cov, const Eigen::MatrixXd& cross, LandmarkInfo info)
{
	const Eigen::Index n = m_x.size(), m = mean.size();
	reserve(n + m);
	m_x.conservativeResize(n + m);
	m_x.segment(n, m) = mean;
	P().block(n, 0, m, n) = cross;
	P().block(0, n, n, m) = cross.transpose();
	P().block(n, n, m, m) = 0.5 * (cov + cov.transpose());
	info.index = n;
	info.size = m;
	m_info.push_back(info);
}

void EkfLocalizer::removeLandmark(size_t j)
{
	const Eigen::Index k = m_info[j].index, m = m_info[j].size;
	const Eigen::Index n = m_x.size(), tail = n - k - m;
	m_x.segment(k, tail) = m_x.tail(tail).eval();
	m_x.conservativeResize(n - m);
	// Rows, then columns, shifted over the removed block (in the buffer,
	// front to back: each source lies after its destination).
	for (Eigen::Index c = 0; c < n; c++)
		for (Eigen::Index r = k; r < n - m; r++) m_Pbuf(r, c) = m_Pbuf(r + m, c);
	for (Eigen::Index c = k; c < n - m; c++) m_Pbuf.col(c).head(n - m) = m_Pbuf.col(c + m).head(n - m);
	m_info.erase(m_info.begin() + static_cast<long>(j));
	for (size_t i = j; i < m_info.size(); i++) m_info[i].index -= m;
}

void EkfLocalizer::pruneLandmarks(bool vertical)
{
	for (size_t j = m_info.size(); j-- > 0;)
		if (m_info[j].vertical() == vertical && m_info[j].observations <= 1 &&
			frames(vertical) - m_info[j].firstFrame > options.landmark_probation_steps)
			removeLandmark(j);
}

void EkfLocalizer::applyCorrection(
	const HeldCorrection& c, Eigen::Index k, mrpt::poses::CPosePDFGaussian& pose)
{
	const Eigen::Matrix3d Kk = c.K.block<3, 3>(k, 0);
	const Eigen::Vector3d dx = Kk * c.nu;
	pose.mean = mrpt::poses::CPose2D(
		pose.mean.x() + dx.x(), pose.mean.y() + dx.y(),
		mrpt::math::wrapToPi(pose.mean.phi() + dx.z()));
	const Eigen::Matrix3d cov = pose.cov.asEigen() - Kk * c.S * Kk.transpose();
	pose.cov = mrpt::math::CMatrixDouble33(0.5 * (cov + cov.transpose()));
}

mrpt::poses::CPosePDFGaussian EkfLocalizer::robotPose() const
{
	auto p = poseAt(m_x, covariance().block<3, 3>(kRobot, kRobot), kRobot);
	if (const auto c = heldCorrection()) applyCorrection(*c, kRobot, p);
	return p;
}

EkfLocalizer::Belief EkfLocalizer::belief() const
{
	Belief b{m_x, covariance()};
	if (const auto c = heldCorrection())
	{
		b.x += c->K * c->nu;
		wrapPoseAngles(b.x);
		b.P -= c->K * c->S * c->K.transpose();
	}
	return b;
}

mrpt::poses::CPosePDFGaussian EkfLocalizer::keyframePose() const
{
	auto p = poseAt(m_x, covariance().block<3, 3>(kClone, kClone), kClone);
	if (const auto c = heldCorrection()) applyCorrection(*c, kClone, p);
	return p;
}

std::vector<EstimatedLandmark> EkfLocalizer::landmarks() const
{
	const auto c = heldCorrection();
	std::vector<EstimatedLandmark> out;
	// The 2-entry block at state index i, with the held match applied.
	auto block = [&](Eigen::Index i, Eigen::Vector2d& mean, Eigen::Matrix2d& cov) {
		mean = m_x.segment<2>(i);
		cov = P().block<2, 2>(i, i);
		if (!c) return;
		const Eigen::Matrix<double, 2, 3> Ki = c->K.block<2, 3>(i, 0);
		mean += Ki * c->nu;
		cov -= Ki * c->S * Ki.transpose();
	};
	for (size_t j = 0; j < m_info.size(); j++)
	{
		const Eigen::Index k = landmarkIndex(j);
		EstimatedLandmark l;
		l.id = m_info[j].id;
		block(k, l.mean, l.covariance);
		l.observations = m_info[j].observations;
		if (m_info[j].vertical())
		{
			Eigen::Vector2d h;
			Eigen::Matrix2d Ph;
			block(k + 2, h, Ph);
			l.vertical = true;
			l.wall = m_info[j].wall;
			l.lLow = h[0];
			l.lHigh = h[1];
			l.sigmaLow = std::sqrt(std::max(0.0, Ph(0, 0)));
			l.sigmaHigh = std::sqrt(std::max(0.0, Ph(1, 1)));
		}
		out.push_back(l);
	}
	return out;
}
}  // namespace featloc
