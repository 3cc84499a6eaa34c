#pragma once
#include <mrpt/poses/CPosePDFGaussian.h>

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "featloc/ekf/EkfOptions.h"
#include "featloc/ekf/EstimatedLandmark.h"
#include "featloc/ekf/LandmarkObservation.h"

namespace featloc
{
/** The EKF front end: the robot pose, a clone of the pose at the current
 * keyframe scan, and 2-D point landmarks, with their joint covariance.
 *
 * State x = [robot (x, y, yaw); keyframe clone (x, y, yaw); landmark 1 (x,
 * y); ...], all in the world frame. Plain Eigen rather than MRPT's
 * CKalmanFilterCapable: that template has one observation-noise matrix for
 * all observations of a step (ours each bring their own covariance) and no
 * place for a cloned pose, which is neither vehicle nor feature.
 *
 * - predict(u): x_r <- x_r (+) u with the odometry increment u (SE(2)
 *   composition, MRPT's Jacobians J_x, J_u): P_rr <- J_x P_rr J_x^T +
 *   J_u Q J_u^T, the robot's cross-covariances <- J_x P_r*.
 * - updateRelativeMotion(z): the scan matcher measured the motion from the
 *   keyframe scan to this one, z = x_c^-1 (+) x_r (stochastic cloning,
 *   Roumeliotis & Burdick 2002). The clone is correlated with the robot, so
 *   the update corrects both, and the odometry, which only gave the matcher
 *   its starting point, is not counted twice: prediction and match are two
 *   independent measurements of the same motion. A match whose
 *   Mahalanobis^2 against the prediction exceeds matcher_gate_chi2 is not
 *   used (the reason says by how much).
 * - cloneKeyframe(): the clone becomes a copy of the robot pose (with its
 *   covariance and correlations), when the pipeline starts a new keyframe.
 * - updateLandmarks(observations): each observation is a point in the robot
 *   frame with its own covariance, with or without identity. Known
 *   identities pair with their landmark; the others are associated by
 *   joint compatibility (JointCompatibilityBranchAndBound) or nearest
 *   neighbour, after individual Mahalanobis gating. Paired observations
 *   update the state together; observations compatible with no landmark
 *   start new ones (inverse observation model with its Jacobians);
 *   observations compatible with some landmark but left unpaired by the
 *   joint test are ambiguous and ignored; so are observations of a known
 *   identity whose innovation fails the individual gate. A landmark seen
 *   only once is removed landmark_probation_steps steps later.
 *
 * Updates use P <- P - K S K^T (symmetrised); angles are wrapped. */
class EkfLocalizer
{
   public:
	EkfLocalizer() = default;
	explicit EkfLocalizer(const EkfOptions& o) : options(o) {}

	EkfOptions options;

	/** Robot and clone at `initial`, no landmarks. */
	void reset(const mrpt::poses::CPosePDFGaussian& initial);

	void predict(const mrpt::poses::CPosePDFGaussian& increment);

	void cloneKeyframe();

	struct MotionUpdate
	{
		bool used = false;
		double mahalanobis2 = 0;  //!< of the innovation
		std::string reason;	 //!< why not used
	};
	/** `motion`: the robot's motion from the keyframe scan to the current
	 * one, with its covariance (already scaled as the caller wants). */
	MotionUpdate updateRelativeMotion(const mrpt::poses::CPosePDFGaussian& motion);

	struct LandmarkUpdate
	{
		size_t observed = 0, associated = 0, added = 0;
		size_t ambiguous = 0;  //!< compatible with a landmark, left unpaired
		size_t rejected = 0;  //!< known identity, implausible innovation
		double jointMahalanobis2 = 0;  //!< of the associated innovations
	};
	LandmarkUpdate updateLandmarks(const std::vector<LandmarkObservation>& observations);

	mrpt::poses::CPosePDFGaussian robotPose() const;
	mrpt::poses::CPosePDFGaussian keyframePose() const;
	std::vector<EstimatedLandmark> landmarks() const;
	size_t landmarkCount() const { return m_info.size(); }
	const Eigen::VectorXd& state() const { return m_x; }
	const Eigen::MatrixXd& covariance() const { return m_P; }

	/** Predicted observation of landmark j from the current state, and its
	 * Jacobians in the robot pose (2x3) and the landmark (2x2). */
	Eigen::Vector2d predictObservation(
		size_t j, Eigen::Matrix<double, 2, 3>* Hr = nullptr, Eigen::Matrix2d* Hl = nullptr) const;

   private:
	static constexpr int kRobot = 0, kClone = 3, kLandmarks = 6;

	/** x <- x + K nu, P <- P - K S K^T for H (m x n), innovation nu, noise R. */
	void update(const Eigen::MatrixXd& H, const Eigen::VectorXd& nu, const Eigen::MatrixXd& R);
	/** The observation rows of pairs (observation i, landmark j): H, nu, R. */
	void stack(
		const std::vector<LandmarkObservation>& obs,
		const std::vector<std::pair<size_t, size_t>>& pairs, Eigen::MatrixXd& H,
		Eigen::VectorXd& nu, Eigen::MatrixXd& R) const;
	double jointMahalanobis2(
		const std::vector<LandmarkObservation>& obs,
		const std::vector<std::pair<size_t, size_t>>& pairs) const;
	void addLandmark(const LandmarkObservation& o);
	void removeLandmark(size_t j);
	void pruneLandmarks();

	struct LandmarkInfo
	{
		int64_t id = -1;
		unsigned int observations = 0;
		uint64_t firstStep = 0;
	};
	Eigen::VectorXd m_x;
	Eigen::MatrixXd m_P;
	std::vector<LandmarkInfo> m_info;
	uint64_t m_step = 0;  //!< predictions so far
};
}  // namespace featloc
