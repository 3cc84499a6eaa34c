#include "featloc/matchers/MotionConstraintCheck.h"

#include <mrpt/core/bits_math.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <cstdio>

namespace featloc
{
namespace
{
/** Eigenvalue ratio below which an information matrix is singular. */
constexpr double kSingularRatio = 1e-12;
}  // namespace

MotionConstraintCheck::MotionConstraintCheck(
	double maxTranslationSigma, double maxRotationSigma, std::string subject, std::string hint)
	: m_maxTranslationSigma(maxTranslationSigma),
	  m_maxRotationSigma(maxRotationSigma),
	  m_subject(std::move(subject)),
	  m_hint(std::move(hint))
{
}

std::string MotionConstraintCheck::describe(Eigen::Vector3d v) const
{
	// Canonical sign: the direction is reported with x >= 0.
	if (v[0] < 0 || (v[0] == 0 && v[1] < 0)) v = -v;
	if (std::abs(v[2]) > 0.7 * v.norm()) return m_subject + " leave the rotation unconstrained";
	// Rounded to the printed precision, without "-0.00".
	auto show = [](double c) { return std::abs(c) < 0.005 ? 0.0 : c; };
	const double len = std::hypot(v[0], v[1]);
	char buf[128];
	std::snprintf(buf, sizeof(buf), "(%.2f, %.2f)", show(v[0] / len), show(v[1] / len));
	return m_subject + " leave the translation along direction " + buf +
		" of the reference scan unconstrained (" + m_hint + ")";
}

std::string MotionConstraintCheck::singular(const Eigen::Matrix3d& B) const
{
	const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(B);
	if (eig.eigenvalues()[2] > 0 && eig.eigenvalues()[0] >= kSingularRatio * eig.eigenvalues()[2])
		return "";
	return describe(eig.eigenvectors().col(0));
}

std::string MotionConstraintCheck::tooUncertain(const Eigen::Matrix3d& C) const
{
	// The weak directions of the information matrix are those of C.
	const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> tr(C.topLeftCorner<2, 2>());
	const double worst = std::sqrt(std::max(0.0, tr.eigenvalues()[1]));
	char buf[128];
	if (worst > m_maxTranslationSigma)
	{
		const Eigen::Vector2d d = tr.eigenvectors().col(1);
		std::snprintf(buf, sizeof(buf), " (sigma %.2f m > max_translation_sigma)", worst);
		return describe(Eigen::Vector3d(d[0], d[1], 0)) + buf;
	}
	const double rot = std::sqrt(std::max(0.0, C(2, 2)));
	if (rot > m_maxRotationSigma)
	{
		std::snprintf(buf, sizeof(buf), " (sigma %.1f deg > max_rotation_sigma_DEG)",
			mrpt::RAD2DEG(rot));
		return m_subject + " leave the rotation unconstrained" + buf;
	}
	return "";
}
}  // namespace featloc
