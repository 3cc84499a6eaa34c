#pragma once
#include <Eigen/Core>
#include <string>

namespace featloc
{
/** Decides whether a matcher's estimate is constrained in every direction
 * and, when it is not, says which direction is free, in words a user can
 * act on ("the translation along direction (1.00, 0.00) of the reference
 * scan is unconstrained (...as in a corridor)"). Shared by the matchers so
 * that they fail alike. */
class MotionConstraintCheck
{
   public:
	/** `subject`: what constrains the motion ("the matched features");
	 * `hint`: why a translation can be free ("all matched lines parallel to
	 * it, as in a corridor"). */
	MotionConstraintCheck(
		double maxTranslationSigma, double maxRotationSigma, std::string subject,
		std::string hint);

	/** The reason for an information matrix `B` (3x3, t_x t_y w) that is
	 * singular, or "" when it is not. */
	std::string singular(const Eigen::Matrix3d& B) const;

	/** The reason when the covariance is wider than the limits along its
	 * weakest translation direction or in rotation, or "". */
	std::string tooUncertain(const Eigen::Matrix3d& cov) const;

	/** The sentence for a free (t_x, t_y, w) direction. */
	std::string describe(Eigen::Vector3d direction) const;

   private:
	double m_maxTranslationSigma, m_maxRotationSigma;
	std::string m_subject, m_hint;
};
}  // namespace featloc
