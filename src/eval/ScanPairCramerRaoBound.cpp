#include "featloc/eval/ScanPairCramerRaoBound.h"

#include <mrpt/poses/CPosePDFGaussian.h>

#include <Eigen/Dense>
#include <cmath>

namespace featloc
{
namespace
{
/** The inverse of a symmetric information matrix, or false when it is
 * singular to working precision (its smallest eigenvalue under 1e-9 of its
 * largest). */
bool invertInformation(const mrpt::math::CMatrixDouble33& info, mrpt::math::CMatrixDouble33& cov)
{
	const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(info.asEigen());
	const auto& l = es.eigenvalues();
	if (!(l[2] > 0) || !(l[0] > 1e-9 * l[2])) return false;
	cov = mrpt::math::CMatrixDouble33(
		es.eigenvectors() * l.cwiseInverse().asDiagonal() * es.eigenvectors().transpose());
	return true;
}
}  // namespace

ScanPairCramerRaoBound ScanPairCramerRaoBound::of(const mrpt::poses::CPose2D& reference,
	const mrpt::math::CMatrixDouble33& referenceInformation, const mrpt::poses::CPose2D& current,
	const mrpt::math::CMatrixDouble33& currentInformation)
{
	ScanPairCramerRaoBound b;
	mrpt::math::CMatrixDouble33 covRef, covCur;
	if (!invertInformation(referenceInformation, covRef) ||
		!invertInformation(currentInformation, covCur))
		return b;
	mrpt::poses::CPosePDFGaussian relative;
	relative.inverseComposition(mrpt::poses::CPosePDFGaussian(current, covCur),
		mrpt::poses::CPosePDFGaussian(reference, covRef));
	b.bounded = true;
	b.cov = relative.cov;
	const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(b.cov.asEigen().topLeftCorner<2, 2>());
	const double a2 = std::max(0.0, es.eigenvalues()[0]), b2 = std::max(0.0, es.eigenvalues()[1]);
	// The mean over the direction of a Rayleigh-distributed radius (the
	// midpoint rule on a smooth periodic integrand; checked against a
	// Monte-Carlo draw in the tests).
	const int steps = 256;
	double sum = 0;
	for (int k = 0; k < steps; k++)
	{
		const double u = 2 * M_PI * (k + 0.5) / steps;
		sum += std::sqrt(a2 * std::cos(u) * std::cos(u) + b2 * std::sin(u) * std::sin(u));
	}
	b.meanTrans = std::sqrt(M_PI / 2) * sum / steps;
	b.meanYaw = std::sqrt(std::max(0.0, b.cov(2, 2)) * 2 / M_PI);
	return b;
}
}  // namespace featloc
