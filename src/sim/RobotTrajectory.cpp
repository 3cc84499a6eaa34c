#include "featloc/sim/RobotTrajectory.h"

#include <mrpt/math/wrap2pi.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace featloc
{
namespace
{
/** Exact unicycle motion for `dt` with constant v, w (a circular arc). */
mrpt::poses::CPose2D integrate(
	const mrpt::poses::CPose2D& p, double v, double w, double dt)
{
	const double th = p.phi(), th2 = th + w * dt;
	if (std::abs(w) < 1e-12)
		return {p.x() + v * dt * std::cos(th), p.y() + v * dt * std::sin(th), th};
	return {p.x() + v / w * (std::sin(th2) - std::sin(th)),
		p.y() - v / w * (std::cos(th2) - std::cos(th)),
		mrpt::math::wrapToPi(th2)};
}
}  // namespace

RobotTrajectory RobotTrajectory::follow(
	const std::vector<Waypoint>& wps, double initialYaw,
	const RobotPathOptions& o)
{
	if (wps.size() < 2) throw std::invalid_argument("a path needs two waypoints");
	RobotTrajectory traj;
	traj.m_waypoints = wps;
	traj.m_period = o.control_period;
	double pathLength = 0;
	for (size_t i = 1; i < wps.size(); i++)
		pathLength += std::hypot(wps[i].x - wps[i - 1].x, wps[i].y - wps[i - 1].y);
	const double timeLimit = 3 * pathLength / o.speed + 60;

	mrpt::poses::CPose2D pose(wps[0].x, wps[0].y, initialYaw);
	size_t target = 1;
	double t = 0;
	const double dt = o.control_period;
	// Proportional steering with a time constant of a few periods.
	const double gain = std::min(3.0, 0.5 / dt);
	while (target < wps.size())
	{
		const auto& g = wps[target];
		double dist = std::hypot(g.x - pose.x(), g.y - pose.y());
		while (dist < o.goal_tolerance && ++target < wps.size())
			dist = std::hypot(wps[target].x - pose.x(), wps[target].y - pose.y());
		if (target >= wps.size()) break;
		const auto& goal = wps[target];
		const double err = mrpt::math::wrapToPi(
			std::atan2(goal.y - pose.y(), goal.x - pose.x()) - pose.phi());
		const double w = std::clamp(gain * err, -o.max_angular_speed, o.max_angular_speed);
		// Full speed when aligned, none beyond turn_in_place (turn on the
		// spot first), and no overshoot of the goal.
		const double align = std::max(
			0.0, (std::cos(err) - std::cos(o.turn_in_place)) /
				(1 - std::cos(o.turn_in_place)));
		const double v = std::min(goal.speed * align, dist / dt);
		traj.m_samples.push_back({pose, v, w, target});
		pose = integrate(pose, v, w, dt);
		traj.m_length += v * dt;
		t += dt;
		if (t > timeLimit)
		{
			std::ostringstream msg;
			msg << "the simulated robot did not reach waypoint " << target
				<< " (" << goal.x << ", " << goal.y << ") within " << timeLimit
				<< " s; check [Robot] waypoints, speed and goal_tolerance";
			throw std::runtime_error(msg.str());
		}
	}
	traj.m_samples.push_back({pose, 0, 0, wps.size() - 1});	 // at rest at the end
	traj.m_duration = t;
	return traj;
}

RobotTrajectory RobotTrajectory::fromOptions(
	const RobotPathOptions& o, const SimWorld& world,
	mrpt::random::CRandomGenerator& rng)
{
	std::vector<Waypoint> wps;
	if (o.path == "waypoints")
	{
		for (unsigned lap = 0; lap < o.laps; lap++)
			for (size_t i = (lap == 0 ? 0 : 1); i < o.waypoints.size(); i++)
			{
				const auto& r = o.waypoints[i];
				wps.push_back({r[0], r[1], r.size() > 2 ? r[2] : o.speed});
			}
	}
	else
	{
		const mrpt::math::TPoint2D start(o.explore_start[0], o.explore_start[1]);
		if (world.clearance(start) < o.explore_clearance)
			throw std::runtime_error(
				"[Robot] explore_start is closer than explore_clearance to a "
				"wall or obstacle");
		wps.push_back({start.x, start.y, o.speed});
		const auto [lo, hi] = world.bounds();
		mrpt::math::TPoint2D cur = start;
		for (unsigned g = 0; g < o.explore_goals; g++)
		{
			bool found = false;
			for (int attempt = 0; attempt < 2000 && !found; attempt++)
			{
				const mrpt::math::TPoint2D cand(
					rng.drawUniform(lo.x, hi.x), rng.drawUniform(lo.y, hi.y));
				if (std::hypot(cand.x - cur.x, cand.y - cur.y) < 1.0) continue;
				if (world.clearance(cand) < o.explore_clearance) continue;
				if (!world.pathIsClear(cur, cand, o.explore_clearance)) continue;
				wps.push_back({cand.x, cand.y, o.speed});
				cur = cand;
				found = true;
			}
			if (!found)
				throw std::runtime_error(
					"exploration: no reachable free goal found from (" +
					std::to_string(cur.x) + ", " + std::to_string(cur.y) +
					"); lower [Robot] explore_clearance");
		}
	}
	double yaw = 0;
	if (o.initial_yaw == "auto")
		yaw = std::atan2(wps[1].y - wps[0].y, wps[1].x - wps[0].x);
	else
		yaw = mrpt::DEG2RAD(std::stod(o.initial_yaw));
	RobotTrajectory traj = follow(wps, yaw, o);
	if (o.path == "waypoints") traj.requireClearOf(world, "waypoints", 0);
	if (o.kidnap_waypoints.empty()) return traj;
	std::vector<Waypoint> kw;
	for (const auto& r : o.kidnap_waypoints) kw.push_back({r[0], r[1], r.size() > 2 ? r[2] : o.speed});
	auto second = std::make_shared<RobotTrajectory>(
		follow(kw, std::atan2(kw[1].y - kw[0].y, kw[1].x - kw[0].x), o));
	second->requireClearOf(world, "kidnap_waypoints", traj.m_duration);
	traj.m_duration += second->m_duration;
	traj.m_length += second->m_length;
	traj.m_kidnapped = std::move(second);
	return traj;
}

void RobotTrajectory::requireClearOf(const SimWorld& world, const char* key, double t0) const
{
	// Closer than this to a surface counts as touching it (rounding).
	constexpr double kTouching = 1e-9;
	for (size_t i = 0; i + 1 < m_samples.size(); i++)
	{
		const auto& a = m_samples[i].pose;
		const auto& b = m_samples[i + 1].pose;
		if (world.pathIsClear({a.x(), a.y()}, {b.x(), b.y()}, kTouching)) continue;
		const size_t k = m_samples[i].target;
		const Waypoint& from = m_waypoints[k - 1];
		const Waypoint& to = m_waypoints[k];
		std::ostringstream where;
		where << std::fixed << std::setprecision(2) << "(" << b.x() << ", " << b.y()
			  << ") at t = " << t0 + static_cast<double>(i + 1) * m_period << " s";
		std::ostringstream msg;
		msg << "[Robot] " << key << ": the robot's path goes through a wall or obstacle near "
			<< where.str() << ", between waypoints " << k - 1 << " (" << from.x << ", " << from.y << ") and "
			<< k << " (" << to.x << ", " << to.y
			<< "); its scans would be taken from inside it. Move the waypoints into free space";
		throw std::runtime_error(msg.str());
	}
}

mrpt::poses::CPose2D RobotTrajectory::poseAt(double t) const
{
	const double tk = kidnapTime();
	if (m_kidnapped && t >= tk) return m_kidnapped->poseAt(t - tk);
	return ownPoseAt(t);
}

mrpt::poses::CPose2D RobotTrajectory::wheelMotion(double t0, double t1) const
{
	const double tk = kidnapTime();
	if (!m_kidnapped || t1 < tk || t0 >= tk) return poseAt(t1) - poseAt(t0);
	// Up to the end of the first path, then from the start of the second.
	return (ownPoseAt(tk) - ownPoseAt(t0)) + (m_kidnapped->poseAt(t1 - tk) - m_kidnapped->poseAt(0));
}

mrpt::poses::CPose2D RobotTrajectory::ownPoseAt(double t) const
{
	if (t <= 0) return m_samples.front().pose;
	const size_t i = static_cast<size_t>(t / m_period);
	if (i >= m_samples.size() - 1) return m_samples.back().pose;
	const Sample& s = m_samples[i];
	return integrate(s.pose, s.v, s.w, t - static_cast<double>(i) * m_period);
}
}  // namespace featloc
