#pragma once
#include <mrpt/math/CMatrixFixed.h>
#include <mrpt/poses/CPose2D.h>

namespace featloc
{
/** The Cramer-Rao bound of a scan pair's relative pose.
 *
 * Each scan's range measurements carry the Fisher information I_ref, I_cur
 * about the pose that took it (RangeScanFisherInformation); the two scans'
 * noises are independent, so (x_ref, x_cur) has the block-diagonal
 * information diag(I_ref, I_cur) and the relative pose q = x_cur (-) x_ref
 * the bound  J_ref I_ref^-1 J_ref^T + J_cur I_cur^-1 J_cur^T  (its
 * Jacobians: mrpt's CPosePDFGaussian::inverseComposition). That bound holds
 * for an estimator that knew the true surfaces; a scan matcher, which knows
 * only the reference scan, cannot do better (less information).
 *
 * For comparison with the benchmarks' mean absolute errors: the mean
 * |t| and |w| errors of an unbiased estimator whose error is Gaussian with
 * that covariance. With the translation block's eigenvalues a^2, b^2:
 *   E|t| = sqrt(pi / 2) (1 / 2 pi) int_0^2pi sqrt(a^2 cos^2 u + b^2 sin^2 u) du,
 *   E|w| = sigma_w sqrt(2 / pi). */
struct ScanPairCramerRaoBound
{
	/** False when either scan's information is singular (a featureless
	 * corridor, too few beams): some motion is not observable at all. */
	bool bounded = false;
	mrpt::math::CMatrixDouble33 cov;  //!< of (x, y, yaw) of the relative pose
	double meanTrans = 0;  //!< [m] E|t error|
	double meanYaw = 0;	 //!< [rad] E|w error|

	static ScanPairCramerRaoBound of(const mrpt::poses::CPose2D& reference,
		const mrpt::math::CMatrixDouble33& referenceInformation,
		const mrpt::poses::CPose2D& current,
		const mrpt::math::CMatrixDouble33& currentInformation);
};
}  // namespace featloc
