#pragma once
#include <mrpt/poses/CPosePDFGaussian.h>

namespace featloc
{
/** A 2-D pose Gaussian with independent errors: variance sigmaXY^2 in x and
 * in y, sigmaYaw^2 [rad^2] in yaw. The priors, guesses and perturbations of
 * the pipeline, the benchmark and the tests are all of this form. */
mrpt::poses::CPosePDFGaussian diagonalPoseGaussian(
	const mrpt::poses::CPose2D& mean, double sigmaXY, double sigmaYaw);
}  // namespace featloc
