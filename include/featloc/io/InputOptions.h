#pragma once
#include <mrpt/config/CLoadableOptions.h>

#include <string>

namespace featloc
{
/** `[Input]`: which rawlog, which laser, what to do with bad readings. */
struct InputOptions : public mrpt::config::CLoadableOptions
{
	static constexpr const char* kSection = "Input";

	/** Rawlog file (format #1 or #2, .gz or plain). A relative path is
	 * relative to the ini file's folder. The command line can override it. */
	std::string rawlog;
	/** Sensor label of the 2-D laser to use; empty: the log must have only
	 * one. */
	std::string laser_label;
	/** A beam marked valid whose range is NaN, infinite or negative:
	 * "error" stops the run naming entry and beam; "invalidate" treats the
	 * beam as invalid and counts it in the summary. */
	std::string invalid_range_policy = "error";
	/** Stop after this many laser scans (0: the whole log). */
	unsigned int max_scans = 0;
	/** CARMEN logs: where a FLASER message's beams point, "sick" or "even"
	 * (CarmenLogReader::Options::beamAngles). */
	std::string carmen_beam_angles = "sick";

	void loadFromConfigFile(
		const mrpt::config::CConfigFileBase& c,
		const std::string& s) override;
	void saveToConfigFile(
		mrpt::config::CConfigFileBase& c, const std::string& s) const override;
};
}  // namespace featloc
