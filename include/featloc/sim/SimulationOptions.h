#pragma once
#include <mrpt/config/CLoadableOptions.h>

namespace featloc
{
/** `[Simulation]` of a world file: time base, length, seed, output format. */
struct SimulationOptions : public mrpt::config::CLoadableOptions
{
	static constexpr const char* kSection = "Simulation";

	double t0 = 1700000000.0;  //!< [s] UNIX time of the first scan
	double duration = 0;  //!< [s] 0: until the robot reaches its last waypoint
	unsigned int max_scans = 0;	 //!< 0: no limit
	unsigned int seed = 1;	//!< random seed (--seed overrides)
	unsigned int format = 1;  //!< rawlog format: 1 (actions/frames) or 2
	bool compress = true;  //!< gzip the rawlog

	void loadFromConfigFile(
		const mrpt::config::CConfigFileBase& c,
		const std::string& s) override;
	void saveToConfigFile(
		mrpt::config::CConfigFileBase& c, const std::string& s) const override;
};
}  // namespace featloc
