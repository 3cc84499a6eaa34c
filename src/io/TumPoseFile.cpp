#include "featloc/io/TumPoseFile.h"

#include <mrpt/math/CQuaternion.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "featloc/core/InputError.h"

namespace featloc
{
std::vector<TumPoseFile::Row> TumPoseFile::read(const std::string& path)
{
	std::ifstream in(path);
	if (!in) throw InputError("cannot read '" + path + "'");
	std::vector<Row> rows;
	std::string line;
	size_t lineNo = 0;
	while (std::getline(in, line))
	{
		lineNo++;
		const auto first = line.find_first_not_of(" \t\r");
		if (first == std::string::npos || line[first] == '#' || line[first] == '%') continue;
		std::istringstream ss(line);
		double t = 0, v[7];
		bool ok = static_cast<bool>(ss >> t);
		for (double& x : v) ok = ok && static_cast<bool>(ss >> x) && std::isfinite(x);
		const double qn = std::sqrt(v[3] * v[3] + v[4] * v[4] + v[5] * v[5] + v[6] * v[6]);
		if (!ok || !std::isfinite(t) || std::abs(qn - 1) > 0.01)
			throw InputError(
				path + ":" + std::to_string(lineNo) + ": expected a TUM row 't x y z qx qy qz qw' (a unit quaternion)");
		// Rounded quaternions (4 decimals, as papers print them) are normalised.
		const mrpt::math::CQuaternionDouble q(v[6] / qn, v[3] / qn, v[4] / qn, v[5] / qn);
		rows.push_back({t, mrpt::poses::CPose3D(q, v[0], v[1], v[2]), line});
	}
	return rows;
}

const TumPoseFile::Row* TumPoseFile::nearest(const std::vector<Row>& rows, double t, double maxGap)
{
	const Row* best = nullptr;
	for (const auto& r : rows)
		if (std::abs(r.t - t) < maxGap && (!best || std::abs(r.t - t) < std::abs(best->t - t))) best = &r;
	return best;
}
}  // namespace featloc
