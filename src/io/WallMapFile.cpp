#include "featloc/io/WallMapFile.h"

#include <mrpt/config/CConfigFile.h>

#include <fstream>
#include <functional>
#include <sstream>

#include "featloc/config/ConfigValues.h"
#include "featloc/core/ConfigError.h"
#include "featloc/core/ExceptionText.h"
#include "featloc/core/InputError.h"

namespace featloc
{
namespace
{
constexpr double kMinWallLength = 1e-3;	 // [m]

void addPieces(
	const std::string& path, const std::string& section, const std::vector<std::vector<double>>& rows,
	bool closed, std::vector<MapWall>& out)
{
	std::vector<Eigen::Vector2d> pts;
	for (const auto& r : rows) pts.emplace_back(r[0], r[1]);
	if (closed && pts.size() > 2) pts.push_back(pts.front());
	for (size_t i = 0; i + 1 < pts.size(); i++)
	{
		MapWall w{pts[i], pts[i + 1], section + "#" + std::to_string(i)};
		if (w.length() < kMinWallLength)
			throw InputError(
				path + ": [" + section + "] piece " + std::to_string(i) +
				" is a wall of zero length (a point repeated in the polyline)");
		out.push_back(w);
	}
}

/** Calls `visit(cfg, section)` for every section of the world file `path`;
 * the file's own errors and a bad value become InputErrors naming it. */
void forEachWorldSection(const std::string& path,
	const std::function<void(const mrpt::config::CConfigFile&, const std::string&)>& visit)
{
	mrpt::config::CConfigFile cfg;
	try
	{
		cfg.setFileName(path);
	}
	catch (const std::exception& e)
	{
		// MRPT's preprocessor ($env{}, $eval{}) throws without the file's name.
		throw InputError(path + ": " + exceptionText(e));
	}
	std::vector<std::string> sections;
	cfg.getAllSections(sections);
	try
	{
		for (const auto& s : sections) visit(cfg, s);
	}
	catch (const ConfigError& e)
	{
		throw InputError(e.what());
	}
}

std::vector<MapWall> loadWorldFile(const std::string& path)
{
	std::vector<MapWall> out;
	forEachWorldSection(path, [&](const mrpt::config::CConfigFile& cfg, const std::string& s) {
		std::vector<std::vector<double>> rows;
		if (s.rfind("Wall.", 0) == 0)
		{
			bool closed = false;
			config::readRows(cfg, s, "polyline", rows, {2});
			config::read(cfg, s, "closed", closed);
			config::require(rows.size() >= 2, cfg, s, "polyline", "at least two points [x y; x y]");
			addPieces(path, s, rows, closed, out);
		}
		else if (s.rfind("Obstacle.", 0) == 0)
		{
			config::readRows(cfg, s, "polygon", rows, {2});
			if (!rows.empty()) addPieces(path, s, rows, true, out);
		}
	});
	if (out.empty())
		throw InputError(
			path + ": no walls: a map needs [Wall.<name>] polyline or [Obstacle.<name>] polygon "
				   "sections, or lines 'x1 y1 x2 y2'");
	return out;
}

std::vector<MapWall> loadSegmentList(const std::string& path, std::istream& in)
{
	std::vector<MapWall> out;
	std::string line;
	for (size_t n = 1; std::getline(in, line); n++)
	{
		const auto first = line.find_first_not_of(" \t\r");
		if (first == std::string::npos || line[first] == '#' || line[first] == '%') continue;
		std::istringstream ss(line);
		double v[4];
		std::string extra;
		if (!(ss >> v[0] >> v[1] >> v[2] >> v[3]) || (ss >> extra))
			throw InputError(path + ":" + std::to_string(n) + ": expected a wall 'x1 y1 x2 y2' [m]");
		MapWall w{{v[0], v[1]}, {v[2], v[3]}, path + ":" + std::to_string(n)};
		if (!w.a.allFinite() || !w.b.allFinite())
			throw InputError(path + ":" + std::to_string(n) + ": not a finite number");
		if (w.length() < kMinWallLength)
			throw InputError(path + ":" + std::to_string(n) + ": a wall of zero length");
		out.push_back(w);
	}
	if (out.empty()) throw InputError(path + ": no walls (expected lines 'x1 y1 x2 y2')");
	return out;
}

/** Whether `in` holds a world file (sections) rather than a segment list
 * (only numbers); leaves `in` at its start. */
bool isWorldFile(std::ifstream& in)
{
	std::string line;
	bool world = false;
	while (std::getline(in, line))
	{
		const auto first = line.find_first_not_of(" \t\r");
		if (first == std::string::npos || line[first] == '#' || line[first] == '%' || line[first] == ';')
			continue;
		world = line[first] == '[';
		break;
	}
	in.clear();
	in.seekg(0);
	return world;
}
}  // namespace

std::vector<MapWall> WallMapFile::load(const std::string& path)
{
	std::ifstream in(path);
	if (!in) throw InputError("cannot read the map '" + path + "'");
	return isWorldFile(in) ? loadWorldFile(path) : loadSegmentList(path, in);
}

std::vector<MapCircle> WallMapFile::loadCircles(const std::string& path)
{
	std::ifstream in(path);
	if (!in) throw InputError("cannot read the map '" + path + "'");
	if (!isWorldFile(in)) return {};
	std::vector<MapCircle> out;
	forEachWorldSection(path, [&](const mrpt::config::CConfigFile& cfg, const std::string& s) {
		if (s.rfind("Obstacle.", 0) != 0) return;
		std::vector<std::vector<double>> rows;
		config::readRows(cfg, s, "circle", rows, {3});
		if (rows.empty()) return;
		config::require(rows.size() == 1 && rows[0][2] > 0, cfg, s, "circle", "one row [cx cy r] with r > 0");
		out.push_back({{rows[0][0], rows[0][1]}, rows[0][2], s});
	});
	return out;
}
}  // namespace featloc
