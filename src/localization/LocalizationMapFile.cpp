#include "featloc/localization/LocalizationMapFile.h"

#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/maps/CSimpleMap.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/serialization/CArchive.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <limits>

#include "featloc/core/ExceptionText.h"
#include "featloc/core/InputError.h"
#include "featloc/io/WallMapFile.h"

namespace featloc
{
namespace
{
using mrpt::maps::COccupancyGridMap2D;

std::string lower(std::string s)
{
	std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
	return s;
}

bool endsWith(const std::string& s, const std::string& tail)
{
	return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

/** The extension that decides the format: ".gz" stripped first. */
std::string formatExtension(const std::string& path)
{
	std::string p = lower(path);
	if (endsWith(p, ".gz")) p.resize(p.size() - 3);
	const auto dot = p.find_last_of('.');
	const auto slash = p.find_last_of('/');
	if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
	return p.substr(dot);
}

std::shared_ptr<COccupancyGridMap2D> fromSimpleMap(const std::string& path, double resolution)
{
	mrpt::maps::CSimpleMap sm;
	bool ok = false;
	try
	{
		ok = sm.loadFromFile(path);
	}
	catch (const std::exception& e)
	{
		throw InputError("map '" + path + "': not a readable MRPT simplemap: " + exceptionText(e));
	}
	if (!ok) throw InputError("map '" + path + "': not a readable MRPT simplemap");
	size_t scans = 0;
	for (const auto& pair : sm)
		if (pair.sf)
			for (const auto& o : *pair.sf)
				scans += IS_CLASS(*o, mrpt::obs::CObservation2DRangeScan) ? 1 : 0;
	if (scans == 0)
		throw InputError("map '" + path + "': the simplemap's " + std::to_string(sm.size()) +
			" keyframes hold no 2-D laser scan to build a map from");
	auto grid = std::make_shared<COccupancyGridMap2D>();
	grid->setSize(-10, 10, -10, 10, static_cast<float>(resolution));
	// Far beams widen beyond a small cell: insert what the cells can hold.
	grid->insertionOptions.maxDistanceInsertion = 30;
	grid->loadFromSimpleMap(sm);
	return grid;
}

std::shared_ptr<COccupancyGridMap2D> fromGridMap(const std::string& path)
{
	try
	{
		mrpt::io::CFileGZInputStream file(path);
		auto arch = mrpt::serialization::archiveFrom(file);
		auto obj = arch.ReadObject();
		auto grid = std::dynamic_pointer_cast<COccupancyGridMap2D>(obj);
		if (!grid)
			throw InputError("map '" + path + "': holds a " +
				std::string(obj ? obj->GetRuntimeClass()->className : "null object") +
				", not an MRPT COccupancyGridMap2D");
		return grid;
	}
	catch (const InputError&)
	{
		throw;
	}
	catch (const std::exception& e)
	{
		throw InputError("map '" + path + "': not a readable MRPT gridmap: " + exceptionText(e));
	}
}

std::shared_ptr<COccupancyGridMap2D> fromImage(const std::string& path, const LocalizationOptions& o)
{
	auto grid = std::make_shared<COccupancyGridMap2D>();
	mrpt::math::TPoint2D origin(
		std::numeric_limits<double>::max(), std::numeric_limits<double>::max());
	if (o.image_origin.size() == 2) origin = {o.image_origin[0], o.image_origin[1]};
	bool ok = false;
	try
	{
		ok = grid->loadFromBitmapFile(path, static_cast<float>(o.image_resolution), origin);
	}
	catch (const std::exception& e)
	{
		throw InputError("map '" + path + "': not a readable image: " + exceptionText(e));
	}
	if (!ok) throw InputError("map '" + path + "': not a readable image");
	return grid;
}

/** Marks the cells under the point p(s), s in [0, 1], occupied. */
template <class Curve>
void drawCurve(
	COccupancyGridMap2D& g, double length, const mrpt::math::TPoint2D& offset, const Curve& p)
{
	// A quarter cell apart: no cell the curve crosses is skipped.
	const int n = std::max(2, static_cast<int>(std::ceil(4 * length / g.getResolution())) + 1);
	for (int i = 0; i < n; i++)
	{
		const Eigen::Vector2d q = p(static_cast<double>(i) / (n - 1));
		g.setCell(g.x2idx(q.x() + offset.x), g.y2idx(q.y() + offset.y), 0.0f);
	}
}

std::shared_ptr<COccupancyGridMap2D> fromWorld(
	const std::string& path, double resolution, mrpt::math::TPoint2D& offset)
{
	const auto walls = WallMapFile::load(path);
	const auto circles = WallMapFile::loadCircles(path);
	Eigen::Vector2d lo = walls.front().a, hi = lo;
	for (const auto& w : walls)
	{
		lo = lo.cwiseMin(w.a).cwiseMin(w.b);
		hi = hi.cwiseMax(w.a).cwiseMax(w.b);
	}
	for (const auto& c : circles)
	{
		const Eigen::Vector2d r(c.radius, c.radius);
		lo = lo.cwiseMin(c.centre - r);
		hi = hi.cwiseMax(c.centre + r);
	}
	constexpr double kMargin = 1.0;	 // [m] free cells around the building
	const double cells = (hi.x() - lo.x() + 2 * kMargin) * (hi.y() - lo.y() + 2 * kMargin) /
		(resolution * resolution);
	if (cells > 4e8)
		throw InputError("map '" + path + "': " + std::to_string(static_cast<long long>(cells)) +
			" cells at grid_resolution " + std::to_string(resolution) +
			" m: too large (raise [Localization] grid_resolution)");
	auto grid = std::make_shared<COccupancyGridMap2D>();
	// MRPT puts cell edges on multiples of the resolution, where walls on
	// round coordinates lie: a beam would enter such a wall's cell at the
	// wall from one side and a cell early from the other, a bias of the
	// whole run. The grid's frame is shifted by half a cell (`offset`), so
	// that the walls run through cell centres.
	const double half = 0.5 * resolution;
	offset = {half, half};
	grid->setSize(static_cast<float>(lo.x() - kMargin), static_cast<float>(hi.x() + kMargin),
		static_cast<float>(lo.y() - kMargin), static_cast<float>(hi.y() + kMargin),
		static_cast<float>(resolution), 1.0f);
	for (const auto& w : walls)
		drawCurve(*grid, w.length(), offset,
			[&](double s) -> Eigen::Vector2d { return w.a + s * (w.b - w.a); });
	for (const auto& c : circles)
		drawCurve(*grid, 2 * M_PI * c.radius, offset, [&](double s) -> Eigen::Vector2d {
			return c.centre + c.radius * Eigen::Vector2d(std::cos(2 * M_PI * s), std::sin(2 * M_PI * s));
		});
	return grid;
}
}  // namespace

LocalizationMap LocalizationMapFile::load(const LocalizationOptions& o)
{
	const std::string& path = o.map;
	if (!std::ifstream(path)) throw InputError("cannot read the map '" + path + "' ([Localization] map)");
	const std::string ext = formatExtension(path);
	std::shared_ptr<COccupancyGridMap2D> grid;
	std::string kind;
	mrpt::math::TPoint2D offset(0, 0);
	if (ext == ".simplemap")
		grid = fromSimpleMap(path, o.grid_resolution), kind = "simplemap";
	else if (ext == ".gridmap")
		grid = fromGridMap(path), kind = "gridmap";
	else if (ext == ".png" || ext == ".pgm" || ext == ".bmp" || ext == ".jpg" || ext == ".jpeg")
		grid = fromImage(path, o), kind = "image";
	else
		grid = fromWorld(path, o.grid_resolution, offset), kind = "world";
	LocalizationMap map(std::move(grid), path, kind, offset);
	if (map.occupiedCells().empty())
		throw InputError("map '" + path + "' (" + kind +
			"): no occupied cell: nothing for a scan to be matched against");
	return map;
}
}  // namespace featloc
