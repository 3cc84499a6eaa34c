#pragma once
#include <mrpt/config/CLoadableOptions.h>

#include <string>

namespace featloc
{
/** `[Evaluation]`: optional ground truth that featloc-run compares its
 * trajectory against at the end of the run (the same metrics as
 * featloc-eval). */
struct EvaluationOptions : public mrpt::config::CLoadableOptions
{
	static constexpr const char* kSection = "Evaluation";

	/** Ground-truth trajectory (TUM, or "t x y yaw" rows); empty: none.
	 * Relative: to the ini's folder. */
	std::string ground_truth;
	/** [s] estimate and ground-truth rows further apart in time are not
	 * associated. */
	double max_time_difference = 0.02;
	/** Align the estimate to the ground truth before the ATE (a run
	 * relative to its start); false: compare in the ground truth's frame
	 * (localization in a known map, whose frame the ground truth shares). */
	bool align = true;

	void loadFromConfigFile(
		const mrpt::config::CConfigFileBase& c,
		const std::string& s) override;
	void saveToConfigFile(
		mrpt::config::CConfigFileBase& c, const std::string& s) const override;
};
}  // namespace featloc
