#include "featloc/sim/WorldPlot.h"

#include <algorithm>

#include "featloc/plot/PlotCanvas.h"

namespace featloc
{
void WorldPlot::write(
	const std::string& pngPath, const SimWorld& world,
	const RobotTrajectory& trajectory, const std::string& title)
{
	const auto [lo, hi] = world.bounds();
	PlotCanvas canvas(lo.x, lo.y, hi.x, hi.y);
	const PlotCanvas::Rgb wall{30, 30, 30}, obstacle{120, 90, 60},
		person{240, 120, 20}, robot{30, 80, 230}, door{150, 40, 160};
	for (const auto& s : world.segments())
		canvas.line({s.a.x, s.a.y}, {s.b.x, s.b.y},
			s.object.rfind("Obstacle.", 0) == 0 ? obstacle : wall, 2);
	for (const auto& c : world.circles())
		canvas.circle({c.centre.x, c.centre.y}, c.radius, obstacle, true);
	for (const auto& a : world.agents())
	{
		std::vector<PlotCanvas::Point> route;
		for (const auto& w : a.params().waypoints) route.push_back({w.x, w.y});
		canvas.polyline(route, person, 1);
		canvas.marker(route.front(), person, 5);
	}
	// A swinging door at each of its keyframes.
	for (const auto& d : world.doors())
		for (const auto& [t, angle] : d.params().swing)
		{
			const WallSegment s = d.segmentAt(t);
			canvas.line({s.a.x, s.a.y}, {s.b.x, s.b.y}, door, 1);
		}
	std::vector<PlotCanvas::Point> path;
	const double step = std::max(0.05, trajectory.duration() / 5000);
	for (double t = 0; t <= trajectory.duration(); t += step)
	{
		const auto p = trajectory.poseAt(t);
		path.push_back({p.x(), p.y()});
	}
	canvas.polyline(path, robot, 2);
	if (!path.empty()) canvas.marker(path.front(), robot, 7);
	canvas.title(title);
	canvas.legend("walls", wall);
	canvas.legend("obstacles", obstacle);
	if (!world.agents().empty()) canvas.legend("routes (people, carts)", person);
	if (!world.doors().empty()) canvas.legend("doors (each keyframe)", door);
	canvas.legend("robot path (circle: start)", robot);
	canvas.save(pngPath);
}
}  // namespace featloc
