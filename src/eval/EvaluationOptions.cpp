#include "featloc/eval/EvaluationOptions.h"

#include "featloc/config/ConfigValues.h"

namespace featloc
{
void EvaluationOptions::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	using namespace featloc::config;
	read(c, s, "ground_truth", ground_truth);
	read(c, s, "max_time_difference", max_time_difference);
	read(c, s, "align", align);
	require(max_time_difference > 0, c, s, "max_time_difference", "> 0");
}

void EvaluationOptions::saveToConfigFile(
	mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	using namespace featloc::config;
	write(c, s, "ground_truth", ground_truth,
		"ground-truth trajectory (TUM or t x y yaw); empty = none");
	write(c, s, "max_time_difference", max_time_difference,
		"[s] max time gap when associating estimate and ground truth");
	write(c, s, "align", align,
		"align the estimate to the ground truth before the ATE (false: in the ground truth's "
		"frame, for localization in a known map)");
}
}  // namespace featloc
