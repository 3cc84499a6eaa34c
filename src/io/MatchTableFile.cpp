#include "featloc/io/MatchTableFile.h"

#include <fstream>
#include <sstream>

#include "featloc/core/InputError.h"
#include "featloc/math/CovarianceFromUpperTriangle.h"

namespace featloc
{
const char* MatchTableFile::header()
{
	return "featloc scan matches: t ref_t status used iterations time_ms goodness "
		   "ref_points cur_points guess_x guess_y guess_yaw est_x est_y est_yaw c_xx c_xy "
		   "c_xyaw c_yy c_yyaw c_yawyaw g_xx g_xy g_xyaw g_yy g_yyaw g_yawyaw a_xx a_xy a_xyaw "
		   "a_yy a_yyaw a_yawyaw reason (s, m, rad; status ok|overruled|failed|gate; c: estimate, g: "
		   "guess, a: gate allowance covariances)";
}

std::vector<MatchTableFile::Row> MatchTableFile::read(const std::string& path)
{
	std::ifstream in(path);
	if (!in) throw InputError("cannot open match table '" + path + "'");
	std::vector<Row> rows;
	std::string line;
	for (size_t lineNo = 1; std::getline(in, line); lineNo++)
	{
		if (line.empty() || line[0] == '#') continue;
		std::istringstream ss(line);
		Row r;
		int used = 0;
		double c[18];
		ss >> r.t >> r.referenceT >> r.status >> used >> r.iterations >> r.timeMs >>
			r.goodness >> r.referencePoints >> r.currentPoints >> r.guess.x >> r.guess.y >>
			r.guess.phi >> r.estimate.x >> r.estimate.y >> r.estimate.phi;
		for (double& v : c) ss >> v;
		if (!ss || (r.status != "ok" && r.status != "failed" && r.status != "gate" &&
						   r.status != "overruled"))
			throw InputError(
				path + ":" + std::to_string(lineNo) + ": not a match-table row (" + header() + ")");
		r.used = used != 0;
		r.cov = covarianceFromUpperTriangle(c);
		r.guessCov = covarianceFromUpperTriangle(c + 6);
		r.gateAllowance = covarianceFromUpperTriangle(c + 12);
		std::getline(ss >> std::ws, r.reason);
		if (r.reason == "-") r.reason.clear();
		rows.push_back(std::move(r));
	}
	return rows;
}
}  // namespace featloc
