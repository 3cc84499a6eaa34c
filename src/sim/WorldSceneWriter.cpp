#include "featloc/sim/WorldSceneWriter.h"

#include <mrpt/opengl/CBox.h>
#include <mrpt/opengl/CCylinder.h>
#include <mrpt/opengl/CGridPlaneXY.h>
#include <mrpt/opengl/COpenGLScene.h>
#include <mrpt/opengl/CSetOfLines.h>
#include <mrpt/opengl/stock_objects.h>
#include <mrpt/poses/CPose3D.h>

#include <cmath>
#include <functional>
#include <stdexcept>

namespace featloc
{
namespace
{
constexpr double kWallHeight = 1.0;	 // [m]
constexpr double kWallThickness = 0.05;	 // [m]

/** A stable, pale colour per texture name. */
mrpt::img::TColorf colourOf(const std::string& texture)
{
	const size_t h = std::hash<std::string>{}(texture);
	return mrpt::img::TColorf(
		0.45f + 0.4f * static_cast<float>(h % 97) / 96.0f,
		0.45f + 0.4f * static_cast<float>((h / 97) % 89) / 88.0f,
		0.45f + 0.4f * static_cast<float>((h / 8633) % 83) / 82.0f);
}
}  // namespace

void WorldSceneWriter::write(
	const std::string& path, const SimWorld& world,
	const RobotTrajectory& trajectory)
{
	mrpt::opengl::COpenGLScene scene;
	const auto [lo, hi] = world.bounds();
	auto grid = mrpt::opengl::CGridPlaneXY::Create(
		std::floor(lo.x) - 1, std::ceil(hi.x) + 1, std::floor(lo.y) - 1,
		std::ceil(hi.y) + 1, 0, 1.0);
	grid->setColor(0.75f, 0.75f, 0.75f, 0.6f);
	scene.insert(grid);

	for (const auto& s : world.segments())
	{
		const double len = std::hypot(s.b.x - s.a.x, s.b.y - s.a.y);
		auto box = mrpt::opengl::CBox::Create(
			mrpt::math::TPoint3D(0, -kWallThickness / 2, 0),
			mrpt::math::TPoint3D(len, kWallThickness / 2, kWallHeight));
		box->setPose(mrpt::poses::CPose3D(
			s.a.x, s.a.y, 0, std::atan2(s.b.y - s.a.y, s.b.x - s.a.x), 0, 0));
		box->setColor(colourOf(s.texture));
		box->setName(s.object);
		scene.insert(box);
	}
	for (const auto& c : world.circles())
	{
		auto cyl = mrpt::opengl::CCylinder::Create(
			static_cast<float>(c.radius), static_cast<float>(c.radius),
			static_cast<float>(kWallHeight));
		cyl->setLocation(c.centre.x, c.centre.y, 0);
		cyl->setColor(colourOf(c.texture));
		cyl->setName(c.object);
		scene.insert(cyl);
	}
	for (const auto& agent : world.agents())
	{
		const auto& p = agent.params();
		auto route = mrpt::opengl::CSetOfLines::Create();
		route->setColor(0.9f, 0.4f, 0.1f);
		for (size_t i = 1; i < p.waypoints.size(); i++)
			route->appendLine(
				p.waypoints[i - 1].x, p.waypoints[i - 1].y, 0.01,
				p.waypoints[i].x, p.waypoints[i].y, 0.01);
		scene.insert(route);
		auto person = mrpt::opengl::CCylinder::Create(0.2f, 0.2f, 1.7f);
		person->setLocation(p.waypoints[0].x, p.waypoints[0].y, 0);
		person->setColor(0.9f, 0.4f, 0.1f, 0.7f);
		person->setName(p.name);
		scene.insert(person);
	}
	auto robotPath = mrpt::opengl::CSetOfLines::Create();
	robotPath->setColor(0.1f, 0.3f, 1.0f);
	robotPath->setLineWidth(2.0f);
	const double step = 0.1;
	auto prev = trajectory.poseAt(0);
	for (double t = step; t <= trajectory.duration() + step; t += step)
	{
		const auto cur = trajectory.poseAt(std::min(t, trajectory.duration()));
		robotPath->appendLine(prev.x(), prev.y(), 0.02, cur.x(), cur.y(), 0.02);
		prev = cur;
	}
	scene.insert(robotPath);
	auto start = mrpt::opengl::stock_objects::CornerXYZSimple(0.5f, 2.0f);
	start->setPose(mrpt::poses::CPose3D(trajectory.poseAt(0)));
	scene.insert(start);

	if (!scene.saveToFile(path))
		throw std::runtime_error("cannot write '" + path + "'");
}
}  // namespace featloc
