#include "featloc/eval/TrajectoryFile.h"

#include <mrpt/math/wrap2pi.h>
#include <mrpt/system/filesystem.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <sstream>

#include "featloc/core/InputError.h"
#include "featloc/math/CovarianceFromUpperTriangle.h"

namespace featloc
{
namespace
{
using Row = std::vector<double>;

/** Calls `onRow(lineNo, values)` for every data line; throws InputError on a
 * field that is not a finite number. */
void forEachRow(
	const std::string& path, const std::function<void(int, const Row&)>& onRow)
{
	if (!mrpt::system::fileExists(path))
		throw InputError("file '" + path + "' does not exist");
	std::ifstream in(path);
	if (!in) throw InputError("file '" + path + "' cannot be read");
	std::string line;
	for (int lineNo = 1; std::getline(in, line); lineNo++)
	{
		for (auto& ch : line)
			if (ch == ',' || ch == '\t' || ch == '\r') ch = ' ';
		const auto first = line.find_first_not_of(' ');
		if (first == std::string::npos || line[first] == '#' || line[first] == '%') continue;
		std::istringstream fields(line);
		Row row;
		std::string tok;
		while (fields >> tok)
		{
			errno = 0;
			char* end = nullptr;
			const double v = std::strtod(tok.c_str(), &end);
			if (errno != 0 || end != tok.c_str() + tok.size() || !std::isfinite(v))
				throw InputError(
					path + ":" + std::to_string(lineNo) + ": '" + tok +
					"' is not a finite number");
			row.push_back(v);
		}
		onRow(lineNo, row);
	}
}

std::string at(const std::string& path, int lineNo)
{
	return path + ":" + std::to_string(lineNo);
}

void requireColumns(
	const std::string& path, int lineNo, const Row& row, size_t n,
	const char* what)
{
	if (row.size() != n)
		throw InputError(
			at(path, lineNo) + ": expected " + std::to_string(n) +
			" columns (" + what + "), found " + std::to_string(row.size()));
}

/** KITTI's camera frame: every rotation is about the y axis (r22 = 1). */
bool isCameraConvention(const Row& r) { return std::abs(r[5] - 1.0) < 1e-6; }

/** Every format with its command-line name and its console description:
 * parseFormat, formatName and formatDescription all read this one list. */
struct FormatInfo
{
	TrajectoryFile::Format format;
	const char* name;
	const char* description;
};
const FormatInfo kFormats[] = {
	{TrajectoryFile::Format::Tum, "tum", "TUM 't x y z qx qy qz qw'"},
	{TrajectoryFile::Format::TimeXYYaw, "txyyaw", "'t x y yaw' (MRPT .GT.txt)"},
	{TrajectoryFile::Format::PosesCov, "poses_cov", "featloc poses_cov.txt"},
	{TrajectoryFile::Format::Relations, "relations", "relations 't1 t2 x y z roll pitch yaw'"},
	{TrajectoryFile::Format::MrptRobotPath, "mrpt_path",
		"MRPT robot path 'x y z yaw pitch roll', no times: rows pair with the estimate's in "
		"order"},
	{TrajectoryFile::Format::Kitti, "kitti",
		"KITTI 3x4 pose rows, no times: rows pair with the estimate's in order"},
};

bool isUnitQuaternion(const Row& r)
{
	const double n2 = r[4] * r[4] + r[5] * r[5] + r[6] * r[6] + r[7] * r[7];
	return std::abs(n2 - 1.0) < 1e-3;
}
}  // namespace

TrajectoryFile::Format TrajectoryFile::detect(const std::string& path)
{
	size_t columns = 0;
	bool allUnitQuaternions = true;
	forEachRow(path, [&](int, const Row& row) {
		if (columns == 0) columns = row.size();
		if (row.size() == 8 && !isUnitQuaternion(row)) allUnitQuaternions = false;
	});
	switch (columns)
	{
		case 6:
			return Format::MrptRobotPath;
		case 12:
			return Format::Kitti;
		case 4:
			return Format::TimeXYYaw;
		case 10:
			return Format::PosesCov;
		case 8:
			return allUnitQuaternions ? Format::Tum : Format::Relations;
		case 0:
			throw InputError("file '" + path + "' has no data rows");
		default:
			throw InputError(
				"file '" + path + "': rows have " + std::to_string(columns) +
				" columns; expected 8 (TUM 't x y z qx qy qz qw' or relations "
				"'t1 t2 x y z roll pitch yaw'), 4 ('t x y yaw') or 10 "
				"(featloc poses_cov.txt)");
	}
}

Trajectory TrajectoryFile::read(const std::string& path, Format format, Format* used)
{
	if (format == Format::Auto) format = detect(path);
	if (used) *used = format;
	if (format == Format::Relations)
		throw InputError(
			"file '" + path +
			"' holds relations (t1 t2 x y z roll pitch yaw), not a trajectory");
	Trajectory traj;
	traj.source = path;
	traj.timed = format != Format::MrptRobotPath && format != Format::Kitti;
	forEachRow(path, [&](int lineNo, const Row& r) {
		TimedPose p;
		switch (format)
		{
			case Format::MrptRobotPath:
				requireColumns(path, lineNo, r, 6, "x y z yaw pitch roll");
				p.t = static_cast<double>(traj.poses.size());
				p.pose = {r[0], r[1], mrpt::math::wrapToPi(r[3])};
				break;
			case Format::Kitti:
				requireColumns(path, lineNo, r, 12, "3x4 pose matrix, row by row");
				p.t = static_cast<double>(traj.poses.size());
				if (isCameraConvention(r))	// z forward, x right: the ground is x-z
					p.pose = {r[11], -r[3], std::atan2(-r[2], r[10])};
				else
					p.pose = {r[3], r[7], std::atan2(r[4], r[0])};
				break;
			case Format::Tum:
				requireColumns(path, lineNo, r, 8, "t x y z qx qy qz qw");
				if (!isUnitQuaternion(r))
					throw InputError(
						at(path, lineNo) + ": quaternion is not unit length");
				p.t = r[0];
				// Yaw of the rotation: atan2(2(qw qz + qx qy), 1 - 2(qy^2 + qz^2)).
				p.pose = {r[1], r[2],
					std::atan2(
						2 * (r[7] * r[6] + r[4] * r[5]),
						1 - 2 * (r[5] * r[5] + r[6] * r[6]))};
				break;
			case Format::TimeXYYaw:
				requireColumns(path, lineNo, r, 4, "t x y yaw");
				p.t = r[0];
				p.pose = {r[1], r[2], mrpt::math::wrapToPi(r[3])};
				break;
			default:  // PosesCov
				requireColumns(path, lineNo, r, 10, "t x y yaw + 6 covariance terms");
				p.t = r[0];
				p.pose = {r[1], r[2], mrpt::math::wrapToPi(r[3])};
				p.hasCovariance = true;
				p.cov = covarianceFromUpperTriangle(&r[4]);
				break;
		}
		if (!traj.poses.empty() && p.t < traj.poses.back().t)
			throw InputError(
				at(path, lineNo) + ": time " + std::to_string(p.t) +
				" is before the previous row's; rows must be in time order");
		if (!traj.poses.empty() && p.t == traj.poses.back().t) traj.repeatedTimes = true;
		traj.poses.push_back(p);
	});
	if (traj.poses.empty())
		throw InputError("file '" + path + "' has no data rows");
	return traj;
}

std::vector<PoseRelation> TrajectoryFile::readRelations(const std::string& path)
{
	std::vector<PoseRelation> out;
	forEachRow(path, [&](int lineNo, const Row& r) {
		requireColumns(path, lineNo, r, 8, "t1 t2 x y z roll pitch yaw");
		PoseRelation rel;
		rel.t1 = r[0];
		rel.t2 = r[1];
		rel.delta = {r[2], r[3], mrpt::math::wrapToPi(r[7])};
		out.push_back(rel);
	});
	if (out.empty()) throw InputError("file '" + path + "' has no relations");
	return out;
}

TrajectoryFile::Format TrajectoryFile::parseFormat(const std::string& name)
{
	if (name == "auto") return Format::Auto;
	std::string known = "auto";
	for (const auto& f : kFormats)
	{
		if (name == f.name) return f.format;
		known += std::string(", ") + f.name;
	}
	throw InputError("unknown trajectory format '" + name + "' (" + known + ")");
}

std::string TrajectoryFile::formatName(Format f)
{
	for (const auto& k : kFormats)
		if (k.format == f) return k.name;
	return "auto";
}

std::string TrajectoryFile::formatDescription(Format f)
{
	for (const auto& k : kFormats)
		if (k.format == f) return k.description;
	return "auto";
}
}  // namespace featloc
