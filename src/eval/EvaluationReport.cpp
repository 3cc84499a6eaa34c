#include "featloc/eval/EvaluationReport.h"
#include "featloc/core/WholeFile.h"

#include <mrpt/core/bits_math.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <nlohmann/json.hpp>
#include <sstream>

namespace featloc
{
namespace
{
std::string row(const char* name, const ErrorStats& s, double scale, const char* unit)
{
	char buf[256];
	std::snprintf(
		buf, sizeof(buf),
		"  %-26s %10.4f %10.4f %10.4f %10.4f %10.4f  %s\n", name,
		s.rmse * scale, s.mean * scale, s.median * scale, s.p95 * scale,
		s.max * scale, unit);
	return buf;
}

nlohmann::json statsJson(const ErrorStats& s)
{
	return {{"count", s.count},	 {"rmse", s.rmse}, {"mean", s.mean},
			{"median", s.median}, {"p95", s.p95},	 {"std", s.stddev},
			{"max", s.max}};
}

nlohmann::json rotationJson(const ErrorStats& s)
{
	auto j = statsJson(s);
	j["unit"] = "deg";
	for (const char* k : {"rmse", "mean", "median", "p95", "std", "max"})
		j[k] = mrpt::RAD2DEG(j[k].get<double>());
	return j;
}
}  // namespace

std::string EvaluationReport::toText() const
{
	std::ostringstream out;
	const std::string header =
		"  metric                           rmse       mean     median        "
		"p95        max\n";
	if (hasTrajectoryMetrics)
	{
		char buf[512];
		std::snprintf(
			buf, sizeof(buf),
			"reference %s (%zu poses), estimate %s (%zu poses): %zu "
			"associated %s\n"
			"%s: x %.4f m, y %.4f m, yaw %.3f "
			"deg\n",
			reference.c_str(), referencePoses, estimate.c_str(), estimatePoses, associated,
			pairedByIndex ? "row by row (no times on one side)"
						  : ("within " + std::to_string(maxTimeDifference).substr(0, 5) + " s").c_str(),
			aligned ? "alignment applied to the estimate"
					: "no alignment (the estimate is in the reference's frame)",
			alignment.x, alignment.y,
			mrpt::RAD2DEG(alignment.phi));
		out << buf << header;
		out << row("ATE translation", ate, 1, "m");
		out << row("ATE rotation", ateRotation, mrpt::RAD2DEG(1.0), "deg");
		out << row("RPE translation (consec.)", rpeTranslation, 1, "m");
		out << row("RPE rotation (consec.)", rpeRotation, mrpt::RAD2DEG(1.0), "deg");
		if (hasNees)
		{
			out << row("NEES (estimate's covariance)", nees, 1, "");
			std::snprintf(buf, sizeof(buf),
				"  NEES within the 95%% chi-square bound (3 dof): %.1f%% of %zu poses "
				"(consistent: mean 3, 95%%)\n",
				100 * neesWithin95, nees.count);
			out << buf;
		}
	}
	if (hasRelations)
	{
		char buf[256];
		std::snprintf(
			buf, sizeof(buf),
			"relations (Kummerle et al. 2009): %zu of %zu matched within "
			"%.3f s\n",
			relationsMatched, relations, maxTimeDifference);
		out << buf << header;
		out << row("relation translation", relationTranslation, 1, "m");
		out << row("relation rotation", relationRotation, mrpt::RAD2DEG(1.0), "deg");
		std::snprintf(
			buf, sizeof(buf),
			"  Kummerle squared errors: translation %.6f m^2 (std %.6f), "
			"rotation %.6f deg^2\n",
			relationTranslation.rmse * relationTranslation.rmse,
			relationTranslation.stddev,
			mrpt::square(mrpt::RAD2DEG(relationRotation.rmse)));
		out << buf;
	}
	return out.str();
}

std::string EvaluationReport::toJson() const
{
	nlohmann::json j;
	j["max_time_difference_s"] = maxTimeDifference;
	j["paired_by_index"] = pairedByIndex;
	j["estimate"] = estimate;
	if (hasTrajectoryMetrics)
	{
		// Absolute, so that the results folder names its reference wherever
		// it is read from (featloc-viewer draws it).
		std::error_code ec;
		const auto absolute = std::filesystem::weakly_canonical(reference, ec);
		j["reference"] = ec || reference.empty() ? reference : absolute.string();
		j["reference_poses"] = referencePoses;
		j["estimate_poses"] = estimatePoses;
		j["associated"] = associated;
		j["alignment"] = {
			{"x", alignment.x},
			{"y", alignment.y},
			{"yaw_deg", mrpt::RAD2DEG(alignment.phi)}};
		j["aligned"] = aligned;
		j["ate_m"] = statsJson(ate);
		j["ate_rotation"] = rotationJson(ateRotation);
		j["rpe_translation_m"] = statsJson(rpeTranslation);
		j["rpe_rotation"] = rotationJson(rpeRotation);
		if (hasNees)
		{
			j["nees"] = statsJson(nees);
			j["nees_within_95"] = neesWithin95;
		}
	}
	if (hasRelations)
	{
		j["relations"] = relations;
		j["relations_matched"] = relationsMatched;
		j["relation_translation_m"] = statsJson(relationTranslation);
		j["relation_rotation"] = rotationJson(relationRotation);
	}
	return j.dump(2);
}
void EvaluationReport::writeNeesSeries(const std::string& path) const
{
	writeWholeFile(path, [&](const std::string& file) { writeNeesRows(file, path); });
}

void EvaluationReport::writeNeesRows(const std::string& file, const std::string& path) const
{
	std::ofstream out(file);
	if (!out) throw std::runtime_error("cannot write '" + path + "'");
	out << "# NEES of each pose against the reference (3 dof; consistent: mean 3): t nees\n";
	char buf[64];
	for (const auto& [t, nees] : neesSeries)
	{
		std::snprintf(buf, sizeof(buf), "%.6f %.6g\n", t, nees);
		out << buf;
	}
	out.close();
	if (!out) throw std::runtime_error("error writing '" + path + "'");
}
}  // namespace featloc
