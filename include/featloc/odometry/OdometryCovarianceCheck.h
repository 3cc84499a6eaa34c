#pragma once
#include <mrpt/poses/CPosePDFGaussian.h>

#include <Eigen/Core>
#include <cstddef>
#include <deque>

namespace featloc
{
/** Checks the odometry covariance against the scan matcher as a run goes,
 * and says by how much to inflate it.
 *
 * Each converged match z (motion from the keyframe scan, covariance R) is
 * compared with the odometry o over the same interval (covariance Q): for a
 * consistent Q, d^2 = e^T (Q + R)^-1 e with e = z - o follows a chi-square
 * law with 3 dof. The check finds the smallest factor s >= 1 for which the
 * *median* of d^2(s) = e^T (s Q + R)^-1 e over the last `window` matches is
 * at most the chi-square median (2.37): the median ignores up to half the
 * matches being wrong, so a bad match cannot make odometry look worse, and
 * s never goes below 1 (odometry is never made more confident than the log
 * says). Matches rejected by a gate must be observed too: leaving them out
 * would keep exactly the evidence the check needs.
 *
 * Until `minSamples` matches were seen the factor is 1. */
class OdometryCovarianceCheck
{
   public:
	explicit OdometryCovarianceCheck(
		size_t window = 30, double quantile = 0.5, size_t minSamples = 3);

	/** `odometry` and `match`: the same motion (from the keyframe scan to
	 * the current one, robot frame), by odometry and by the matcher. */
	void observe(
		const mrpt::poses::CPosePDFGaussian& odometry, const mrpt::poses::CPosePDFGaussian& match);

	/** The factor for the odometry covariance (>= 1). */
	double scale() const { return m_scale; }
	/** The largest factor used during the run. */
	double maxScale() const { return m_maxScale; }
	size_t samples() const { return m_samples; }

   private:
	struct Sample
	{
		Eigen::Vector3d e;
		Eigen::Matrix3d Q, R;
	};
	double quantileMahalanobis2(double s) const;

	size_t m_window;
	double m_quantile;
	size_t m_minSamples;
	std::deque<Sample> m_recent;
	size_t m_samples = 0;
	double m_scale = 1, m_maxScale = 1;
};
}  // namespace featloc
