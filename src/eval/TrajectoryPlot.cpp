#include "featloc/eval/TrajectoryPlot.h"

#include <mrpt/poses/CPose2D.h>

#include <algorithm>
#include <stdexcept>

#include "featloc/plot/PlotCanvas.h"

namespace featloc
{
namespace
{
std::vector<PlotCanvas::Point> positions(
	const Trajectory& t, const mrpt::poses::CPose2D& transform)
{
	std::vector<PlotCanvas::Point> out;
	for (const auto& p : t.poses)
	{
		const auto q = transform + mrpt::poses::CPose2D(p.pose);
		out.push_back({q.x(), q.y()});
	}
	return out;
}
}  // namespace

void TrajectoryPlot::write(
	const std::string& pngPath, const Trajectory& reference,
	const Trajectory& estimate, const mrpt::math::TPose2D& alignment,
	const std::string& title, const std::vector<mrpt::math::TPoint2D>& map)
{
	const auto ref = positions(reference, mrpt::poses::CPose2D());
	const auto est = positions(estimate, mrpt::poses::CPose2D(alignment));
	if (ref.empty() && est.empty())
		throw std::runtime_error("cannot plot '" + pngPath + "': no poses");
	double minX = 1e300, maxX = -1e300, minY = 1e300, maxY = -1e300;
	for (const auto* v : {&ref, &est})
		for (const auto& p : *v)
		{
			minX = std::min(minX, p.x);
			maxX = std::max(maxX, p.x);
			minY = std::min(minY, p.y);
			maxY = std::max(maxY, p.y);
		}
	std::vector<PlotCanvas::Point> mapPoints;
	for (const auto& p : map)
	{
		mapPoints.push_back({p.x, p.y});
		minX = std::min(minX, p.x);
		maxX = std::max(maxX, p.x);
		minY = std::min(minY, p.y);
		maxY = std::max(maxY, p.y);
	}
	PlotCanvas canvas(minX, minY, maxX, maxY);
	const PlotCanvas::Rgb refColour{40, 160, 40}, estColour{220, 30, 30}, mapColour{150, 150, 150};
	canvas.dots(mapPoints, mapColour);
	canvas.polyline(ref, refColour);
	canvas.polyline(est, estColour);
	if (!ref.empty()) canvas.marker(ref.front(), refColour);
	if (!est.empty()) canvas.marker(est.front(), estColour);
	canvas.title(title);
	if (!ref.empty()) canvas.legend("reference", refColour);
	const bool aligned = alignment.x != 0 || alignment.y != 0 || alignment.phi != 0;
	canvas.legend(aligned ? "estimate (aligned)" : "estimate", estColour);
	if (!mapPoints.empty()) canvas.legend("map", mapColour);
	canvas.legend("circle = start", {120, 120, 120});
	canvas.save(pngPath);
}
}  // namespace featloc
