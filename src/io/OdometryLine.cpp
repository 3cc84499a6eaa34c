#include "featloc/io/OdometryLine.h"

#include <cmath>
#include <cstdio>
#include <sstream>
#include <vector>

#include "featloc/core/InputError.h"

namespace featloc
{
std::string OdometryLine::format() const
{
	char buf[200];
	int n = std::snprintf(
		buf, sizeof(buf), "ODOM %.6f %.6f %.6f %.8f", time, pose.x(), pose.y(), pose.phi());
	if (hasVelocities)
		n += std::snprintf(buf + n, sizeof(buf) - static_cast<size_t>(n), " %.6f %.6f", v, w);
	return std::string(buf, static_cast<size_t>(n)) + "\n";
}

std::optional<OdometryLine> OdometryLine::parse(const std::string& raw)
{
	std::string line = raw;
	while (!line.empty() && (line.back() == '\n' || line.back() == '\r')) line.pop_back();
	const auto first = line.find_first_not_of(" \t");
	if (first == std::string::npos || line[first] == '#') return std::nullopt;

	auto bad = [&](const std::string& why) {
		return InputError(
			"odometry line '" + line + "': " + why +
			" (expected 'ODOM <t> <x> <y> <phi> [<v> <w>]')");
	};
	std::istringstream ss(line);
	std::string keyword;
	ss >> keyword;
	if (keyword != "ODOM") throw bad("does not start with ODOM");
	std::vector<double> values;
	std::string field;
	while (ss >> field)
	{
		size_t used = 0;
		double v = 0;
		try
		{
			v = std::stod(field, &used);
		}
		catch (const std::exception&)
		{
			used = 0;
		}
		if (used != field.size() || !std::isfinite(v))
			throw bad("'" + field + "' is not a finite number");
		values.push_back(v);
	}
	if (values.size() != 4 && values.size() != 6)
		throw bad("has " + std::to_string(values.size()) + " numbers, not 4 or 6");
	OdometryLine r;
	r.time = values[0];
	r.pose = mrpt::poses::CPose2D(values[1], values[2], values[3]);
	if (values.size() == 6)
	{
		r.hasVelocities = true;
		r.v = values[4];
		r.w = values[5];
	}
	return r;
}
}  // namespace featloc
