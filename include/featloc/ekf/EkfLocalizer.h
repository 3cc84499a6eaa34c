#pragma once
#include <mrpt/poses/CPosePDFGaussian.h>

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "featloc/ekf/EkfOptions.h"
#include "featloc/ekf/EstimatedLandmark.h"
#include "featloc/ekf/LandmarkObservation.h"
#include "featloc/stereo/StereoWallObservation.h"
#include "featloc/stereo/VerticalLandmarkObservation.h"

namespace featloc
{
/** The EKF front end: the robot pose, a clone of the pose at the current
 * keyframe scan, a clone of the pose of the held match, and 2-D point
 * landmarks, with their joint covariance: one state, one covariance.
 *
 * State x = [robot (x, y, yaw); keyframe clone (x, y, yaw); match clone
 * (x, y, yaw); odometry sampling error (x, y, yaw); odometry direction
 * offset b; landmark 1 (x, y); ...], all in the world frame but the
 * sampling error, which is in the robot frame of the last scan. Plain Eigen
 * rather than MRPT's CKalmanFilterCapable: that template has one
 * observation-noise matrix for all observations of a step (ours each bring
 * their own covariance) and no place for cloned poses, which are neither
 * vehicle nor feature.
 *
 * - predict(u): x_r <- x_r (+) u with the odometry increment u (SE(2)
 *   composition, MRPT's Jacobians J_x, J_u): P_rr <- J_x P_rr J_x^T +
 *   J_u Q J_u^T, the robot's cross-covariances <- J_x P_r*. O(n).
 * - predict(u, Sigma) with Sigma != 0: the odometry was read off the scan's
 *   instant (OdometrySamplingOffset), by e_i at scan i, e_i ~ N(0, Sigma_i).
 *   The reading at scan i is the true pose (+) e_i, so the true motion is
 *   x_i = x_{i-1} (+) e_{i-1} (+) u_i (-) e_i: the error of one reading is
 *   taken back at the next (a moving-average noise, not a random walk).
 *   e_{i-1} is kept in the state (state augmentation for correlated process
 *   noise, Bar-Shalom, Li & Kirubarajan 2001, sec. 8.2), so the filter
 *   weighs the odometry by the error it really has over an interval (two
 *   ends, whatever the interval's length) and a match that shows a reading
 *   was early or late corrects the next step too. With Sigma = 0 throughout
 *   (odometry taken at the scan's time) e stays 0 and this is predict(u).
 * - The odometry's translation is turned by b before it is composed: an
 *   odometry frame turned against the scanner's (a laser mounted a few
 *   degrees off the sensor pose the log gives, or wheels that pull to one
 *   side) makes every step's translation disagree with the matches to the
 *   side. Without b in the state the filter can explain that only by
 *   turning the robot, a little at every match, and its heading drifts
 *   (MRPT's Malaga log: the odometry's steps point 2.6 deg off the
 *   matcher's; doc/benchmarks.md, "Malaga's loop"). b is a constant with
 *   prior sigma odometry_direction_sigma_DEG, learnt from the matches
 *   through its correlation with the robot pose: online odometry
 *   calibration (Roy & Thrun 1999; Martinelli, Tomatis & Siegwart 2007).
 *   Prior sigma 2 deg by default (0: b = 0, not estimated).
 * - Scan matches measure the motion from the keyframe scan to the current
 *   one, z = x_c^-1 (+) x_r (stochastic cloning, Roumeliotis & Burdick
 *   2002): the clone is correlated with the robot, so an update corrects
 *   both, and the odometry, which only gave the matcher its starting
 *   point, is not counted twice. Successive matches from one keyframe share
 *   the keyframe scan and nearly all their error, so only one of them may
 *   be fused: holdRelativeMotion() keeps the latest accepted one pending
 *   (the robot pose at that time is cloned into the match clone, so the
 *   measurement stays exact however far the robot moves on), and
 *   commitHeldMotion() fuses it when the keyframe changes. The views
 *   (robotPose, keyframePose, landmarks) include the held match: they are
 *   the posterior of everything seen so far, computed in O(n) from the
 *   state without it. A match whose Mahalanobis^2 against the prediction
 *   exceeds matcher_gate_chi2 is not used (the reason says by how much).
 * - cloneKeyframe(): the clone becomes a copy of the robot pose (with its
 *   covariance and correlations), when the pipeline starts a new keyframe.
 * - updateLandmarks(observations): each observation is a point in the robot
 *   frame with its own covariance, with or without identity. Individual
 *   gating uses the robot and landmark blocks only (O(1) per pair). Known
 *   identities pair with their landmark when individually plausible and
 *   form the base hypothesis; the others are associated by joint
 *   compatibility with it (JointCompatibilityBranchAndBound, incremental
 *   joint innovation) or by nearest neighbour. Paired observations update
 *   the state together; observations compatible with no landmark start new
 *   ones (inverse observation model with its Jacobians); observations
 *   compatible with some landmark but left unpaired are ambiguous and
 *   ignored; so are known identities whose innovation fails the gate. A
 *   landmark seen only once is removed landmark_probation_steps steps
 *   later.
 * - updateVerticalLandmarks(observations): vertical-line landmarks
 *   [x y l_low l_high] of Moon, Miura & Shirai (section 5), observed
 *   through the constraint of eq. (20) (VerticalLandmarkConstraint). An
 *   observation pairs only with a landmark on its wall with its polarity
 *   whose height range it overlaps, by nearest neighbour within the
 *   position gate (2 dof: a line broken into pieces is still one line);
 *   an observed end enters the update only if it agrees with the
 *   landmark's (1 dof gate). Of the pairs, the
 *   stereo_landmarks_per_frame least uncertain landmarks update the state
 *   (section 4: "a subset of stable landmarks with less uncertainty"),
 *   after dropping, while the subset is not jointly compatible, the pair
 *   farthest from its prediction.
 *   The frame's fitted walls (StereoWallObservation: the line each wall's
 *   disparity pixels make, against the map's wall seen from the robot)
 *   join the same update, each gated alone at landmark_gate_probability
 *   (2 dof) and then with the landmarks' pairs jointly; a wall's fit and
 *   the observations constrained to it share its error (their
 *   cross-covariance J_i Sigma_ab enters R).
 *   Selected features outside the new-landmark gate of every landmark (this
 *   frame's new ones included) start one on-line, at
 *   their position relative to the map's edge (eq. 15) with its rank-1
 *   covariance (eq. 17), uncorrelated with the robot: the map is known.
 *
 * Updates use P <- P - K S K^T (symmetrised) with H restricted to the
 * columns it touches; angles are wrapped. */
class EkfLocalizer
{
   public:
	EkfLocalizer() = default;
	explicit EkfLocalizer(const EkfOptions& o) : options(o) {}

	EkfOptions options;

	/** Robot and clones at `initial`, no landmarks, no held match. */
	void reset(const mrpt::poses::CPosePDFGaussian& initial);

	/** `samplingCovariance`: of the odometry reading's error at this scan
	 * (robot frame at this scan); zero when the odometry is taken at the
	 * scan's time. */
	void predict(
		const mrpt::poses::CPosePDFGaussian& increment,
		const mrpt::math::CMatrixDouble33& samplingCovariance = {});

	/** Commits nothing: the caller commits a held match first if it wants
	 * it (EkfEstimator does, at every new keyframe). */
	void cloneKeyframe();

	struct MotionUpdate
	{
		bool used = false;
		double mahalanobis2 = 0;  //!< of the innovation
		std::string reason;	 //!< why not used
	};
	/** The gate alone: is `motion` (keyframe -> robot, with its covariance
	 * already scaled as the caller wants) plausible against the state
	 * without any held match? O(1). (The odometry's sampling error is in
	 * the state: no allowance is added for it.) */
	MotionUpdate testRelativeMotion(const mrpt::poses::CPosePDFGaussian& motion) const;
	/** Gate and fuse at once. */
	MotionUpdate updateRelativeMotion(const mrpt::poses::CPosePDFGaussian& motion);
	/** Gate and fuse an absolute robot pose in the world (map) frame, with
	 * its covariance: a scan matched against a known map (MapScanTracker).
	 * H is the identity on the robot's block; the clones and landmarks are
	 * corrected through their correlations with the robot. Gated against
	 * the state without the held match, at Mahalanobis^2 `gateChi2`. */
	MotionUpdate updateAbsolutePose(const mrpt::poses::CPosePDFGaussian& z, double gateChi2);
	/** Keeps `motion` (which passed testRelativeMotion) as the keyframe
	 * interval's match, replacing any held one. */
	void holdRelativeMotion(const mrpt::poses::CPosePDFGaussian& motion);
	/** Fuses the held match, if any (match clone vs keyframe clone). */
	void commitHeldMotion();
	bool hasHeldMotion() const { return m_held.has_value(); }

	struct LandmarkUpdate
	{
		size_t observed = 0, associated = 0, added = 0;
		size_t ambiguous = 0;  //!< compatible with a landmark, left unpaired
		size_t rejected = 0;  //!< known identity, implausible innovation
		double jointMahalanobis2 = 0;  //!< of the associated innovations
	};
	LandmarkUpdate updateLandmarks(const std::vector<LandmarkObservation>& observations);

	struct VerticalUpdate
	{
		size_t observed = 0, associated = 0, used = 0, added = 0;
		size_t ambiguous = 0;  //!< compatible with a landmark, left unpaired
		size_t inconsistent = 0;  //!< paired, dropped by the joint gate
		/** Fitted walls: handed in, used, failed their own gate (the rest
		 * of those not used were dropped by the joint gate). */
		size_t wallsObserved = 0, wallsUsed = 0, wallsRejected = 0;
		/** Per wall handed in: its Mahalanobis^2 against the belief and
		 * "used", "failed its gate" or "dropped by the joint gate". */
		std::vector<double> wallMahalanobis2;
		std::vector<std::string> wallOutcome;
		double jointMahalanobis2 = 0;  //!< of the innovations used
		/** Per observation: the landmark it updated or started (index
		 * after the update), or -1. */
		std::vector<int> landmarkOf;
	};
	VerticalUpdate updateVerticalLandmarks(const std::vector<VerticalLandmarkObservation>& observations,
		const std::vector<StereoWallObservation>& walls = {});

	/** Posterior views: the held match included. */
	mrpt::poses::CPosePDFGaussian robotPose() const;
	/** The whole posterior view: the state and covariance with the held
	 * match applied (x + K nu, P - K S K^T; without one, the state).
	 * Landmark observations are gated, associated and linearized at it: the state without the held match
	 * lies the match's whole correction away from it (10 cm and 2 deg
	 * before a stereo pair on moon-lab at 40 Hz, where a landmark 30 cm
	 * off was paired). They are then fused into the state without it
	 * (updateAtBelief), which in the linear case gives the same posterior
	 * as fusing the held match first: Bayes' updates commute. O(n^2). */
	struct Belief
	{
		Eigen::VectorXd x;
		Eigen::MatrixXd P;
	};
	Belief belief() const;
	mrpt::poses::CPosePDFGaussian keyframePose() const;
	std::vector<EstimatedLandmark> landmarks() const;

	size_t landmarkCount() const { return m_info.size(); }
	/** The state and covariance without the held match. */
	const Eigen::VectorXd& state() const { return m_x; }
	Eigen::Block<const Eigen::MatrixXd> covariance() const
	{
		return m_Pbuf.topLeftCorner(m_x.size(), m_x.size());
	}
	/** Index of landmark j's x in the state (point landmarks take 2
	 * entries, vertical-line landmarks 4). */
	Eigen::Index landmarkIndex(size_t j) const { return m_info[j].index; }
	static constexpr Eigen::Index kRobot = 0, kClone = 3, kMatchClone = 6, kSamplingError = 9,
								  kOdometryDirection = 12, kLandmarks = 13;

	/** Predicted observation of landmark j from the current state, and its
	 * Jacobians in the robot pose (2x3) and the landmark (2x2). */
	Eigen::Vector2d predictObservation(
		size_t j, Eigen::Matrix<double, 2, 3>* Hr = nullptr, Eigen::Matrix2d* Hl = nullptr) const;
	/** The same at state x (a Belief's). */
	Eigen::Vector2d predictObservation(const Eigen::VectorXd& x, size_t j,
		Eigen::Matrix<double, 2, 3>* Hr = nullptr, Eigen::Matrix2d* Hl = nullptr) const;

	/** Predicted relative motion from the keyframe clone to the pose at
	 * `from` (kRobot or kMatchClone), and its Jacobians in that pose (Ha)
	 * and the keyframe clone (Hc). */
	Eigen::Vector3d predictRelativeMotion(
		Eigen::Index from, Eigen::Matrix3d* Ha = nullptr, Eigen::Matrix3d* Hc = nullptr) const;

   private:
	struct LandmarkInfo
	{
		int64_t id = -1;
		unsigned int observations = 0;
		/** Its sensor's frame (frames(vertical())) that started it. */
		uint64_t firstFrame = 0;
		Eigen::Index index = 0;	 //!< of its x in the state
		Eigen::Index size = 2;	//!< 2: point (x, y); 4: vertical line (x, y, l_low, l_high)
		/** Vertical lines: the map wall it lies on, its edge's polarity. */
		size_t wall = 0;
		int polarity = 0;
		bool vertical() const { return size == 4; }
	};
	/** The gate of a pose-like innovation nu (x, y, yaw) with covariance S:
	 * used when nu^T S^-1 nu <= chi2; the reason names `what` was tested and
	 * the threshold's config `key`. */
	static MotionUpdate gate(const Eigen::VectorXd& nu, const Eigen::MatrixXd& S, double chi2,
		const char* what, const char* key);
	/** x <- x + K nu, P <- P - K S K^T for an observation whose Jacobian is
	 * `Hc` (m x cols.size()) on the state entries `cols` (zero elsewhere).
	 * Returns the innovation's Mahalanobis^2, nu^T S^-1 nu. */
	double update(
		const std::vector<Eigen::Index>& cols, const Eigen::MatrixXd& Hc,
		const Eigen::VectorXd& nu, const Eigen::MatrixXd& R);
	/** The yaw entries of the robot and its two clones, wrapped to
	 * (-pi, pi] in v (a state, or a difference of two). */
	static void wrapPoseAngles(Eigen::VectorXd& v);
	/** update() of an observation linearized at belief b (Jacobian Hc,
	 * innovation nuAtBelief = z - h(b.x)): h(x) ~ h(b.x) + H (x - b.x)
	 * gives the state's innovation nuAtBelief + H (b.x - x). Returns the
	 * Mahalanobis^2 against the belief, the one its gate used. */
	double updateAtBelief(const Belief& b, const std::vector<Eigen::Index>& cols,
		const Eigen::MatrixXd& Hc, const Eigen::VectorXd& nuAtBelief, const Eigen::MatrixXd& R);
	/** The held match as a correction of the state: K (n x 3), nu. */
	struct HeldCorrection
	{
		Eigen::MatrixXd K;
		Eigen::Vector3d nu;
		Eigen::Matrix3d S;
	};
	std::optional<HeldCorrection> heldCorrection() const;
	/** The pose at state index k with the held correction applied. */
	static void applyCorrection(
		const HeldCorrection& c, Eigen::Index k, mrpt::poses::CPosePDFGaussian& pose);
	void relativeMotionTerms(
		Eigen::Index from, const mrpt::poses::CPosePDFGaussian& z, std::vector<Eigen::Index>& cols,
		Eigen::MatrixXd& H, Eigen::VectorXd& nu) const;
	/** Individual squared distance of observation o to landmark j: O(1). */
	double individualDistance2(const Belief& b, const LandmarkObservation& o, size_t j) const;
	void addLandmark(const LandmarkObservation& o);
	/** Appends a landmark with mean `mean`, covariance `cov` and
	 * cross-covariance `cross` (size x n) with the state. */
	void appendLandmark(
		const Eigen::VectorXd& mean, const Eigen::MatrixXd& cov, const Eigen::MatrixXd& cross,
		LandmarkInfo info);
	/** Mahalanobis^2 of vertical observation z against landmark j (robot and
	 * landmark blocks only), and the constraint's terms. */
	double verticalDistance2(const Belief& b, const VerticalLandmarkObservation& z, size_t j) const;
	/** Mahalanobis^2 of wall observation w against the map (robot block
	 * only), and its terms: nu = z - h, H = dh/dX. */
	double wallDistance2(const Belief& b, const StereoWallObservation& w, Eigen::Vector2d* nu = nullptr,
		Eigen::Matrix<double, 2, 3>* H = nullptr) const;
	/** The stacked eq. (20) constraint of the pairs `paired` (landmark
	 * pairing[i] for observation i = paired[a].second), then the rows of
	 * the walls `wallsUsed`. */
	struct VerticalStack
	{
		std::vector<Eigen::Index> cols;
		Eigen::MatrixXd H, R;
		Eigen::VectorXd nu;
	};
	VerticalStack stackVertical(const Belief& b,
		const std::vector<VerticalLandmarkObservation>& obs, const std::vector<int>& pairing,
		const std::vector<std::pair<double, size_t>>& paired,
		const std::vector<const StereoWallObservation*>& wallsUsed = {}) const;
	void removeLandmark(size_t j);
	/** Removes the landmarks of that kind seen once and past their probation. */
	void pruneLandmarks(bool vertical);
	void clonePose(Eigen::Index to);

	Eigen::VectorXd m_x;
	/** The covariance is the top-left n x n corner of this buffer, which
	 * grows by doubling. */
	Eigen::MatrixXd m_Pbuf;
	Eigen::Block<Eigen::MatrixXd> P() { return m_Pbuf.topLeftCorner(m_x.size(), m_x.size()); }
	Eigen::Block<const Eigen::MatrixXd> P() const { return covariance(); }
	void reserve(Eigen::Index n);
	std::vector<LandmarkInfo> m_info;
	std::optional<mrpt::poses::CPosePDFGaussian> m_held;
	/** Landmark frames so far (updateLandmarks, updateVerticalLandmarks
	 * calls): a landmark's probation counts its own sensor's frames, not
	 * predictions (a 40 Hz laser between 2.5 Hz stereo pairs would end it
	 * before the next pair). */
	uint64_t m_pointFrames = 0, m_verticalFrames = 0;
	uint64_t frames(bool vertical) const { return vertical ? m_verticalFrames : m_pointFrames; }

	friend class LandmarkJointInnovation;
};
}  // namespace featloc
