#include "featloc/math/DiagonalPoseGaussian.h"

namespace featloc
{
mrpt::poses::CPosePDFGaussian diagonalPoseGaussian(
	const mrpt::poses::CPose2D& mean, double sigmaXY, double sigmaYaw)
{
	mrpt::math::CMatrixDouble33 cov;
	cov.setZero();
	cov(0, 0) = cov(1, 1) = sigmaXY * sigmaXY;
	cov(2, 2) = sigmaYaw * sigmaYaw;
	return mrpt::poses::CPosePDFGaussian(mean, cov);
}
}  // namespace featloc
