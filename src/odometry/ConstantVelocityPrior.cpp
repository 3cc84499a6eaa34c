#include "featloc/odometry/ConstantVelocityPrior.h"

#include <mrpt/math/wrap2pi.h>

#include <Eigen/Dense>
#include <cmath>

namespace featloc
{
namespace
{
double seconds(mrpt::Clock::time_point a, mrpt::Clock::time_point b)
{
	return std::chrono::duration<double>(b - a).count();
}

/** V(theta) of the SE(2) exponential: the translation of exp([u, theta])
 * is V u (an arc of constant twist). MRPT 2.5.8's Lie::SE<2>::exp/log
 * only copy [x y phi], which turns a chord into a straight step. */
Eigen::Matrix2d arcMatrix(double theta)
{
	double a = 1, b = 0;  // sin(t)/t, (1 - cos(t))/t
	if (std::abs(theta) > 1e-9)
	{
		a = std::sin(theta) / theta;
		b = (1 - std::cos(theta)) / theta;
	}
	Eigen::Matrix2d V;
	V << a, -b, b, a;
	return V;
}
}  // namespace

void ConstantVelocityPrior::add(mrpt::Clock::time_point t, const mrpt::poses::CPose2D& pose)
{
	if (!m_poses.empty() && t <= m_poses.back().first) return;
	m_poses.emplace_back(t, pose);
	// Keep the newest pose at least `window` old (the velocity's baseline).
	while (m_poses.size() > 2 && seconds(m_poses[1].first, t) >= m_window) m_poses.pop_front();
}

std::optional<mrpt::poses::CPose2D> ConstantVelocityPrior::motionTo(mrpt::Clock::time_point t) const
{
	if (m_poses.size() < 2) return std::nullopt;
	const auto& [t0, p0] = m_poses.front();
	const auto& [t1, p1] = m_poses.back();
	const double span = seconds(t0, t1);
	const double ahead = seconds(t1, t);
	if (span < m_window / 2 || ahead <= 0) return std::nullopt;
	// The window's motion p1 (-) p0 as a constant twist (log on SE(2)),
	// continued for the step's length (exp of the twist times its share).
	const mrpt::poses::CPose2D d = p1 - p0;
	const double theta = mrpt::math::wrapToPi(d.phi());
	const Eigen::Vector2d u = arcMatrix(theta).inverse() * Eigen::Vector2d(d.x(), d.y());
	const double s = ahead / span;
	const Eigen::Vector2d step = arcMatrix(s * theta) * (s * u);
	return mrpt::poses::CPose2D(step.x(), step.y(), s * theta);
}
}  // namespace featloc
