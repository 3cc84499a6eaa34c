#include "featloc/live/DriverQuirks.h"

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/system/string_utils.h>

namespace featloc
{
std::string DriverQuirks::describe(const std::string& driver)
{
	if (driver == "CLMS100Eth")
		return "CLMS100Eth (MRPT 2.5.8) declares the LMS1xx's beams left to right and its 0 m "
			   "no-echo beams valid: featloc-live takes them right to left (the device turns "
			   "counter-clockwise) and the 0 m beams as invalid";
	return "";
}

void DriverQuirks::correct(const std::string& driver, mrpt::obs::CObservation& obs)
{
	if (driver != "CLMS100Eth") return;
	auto* scan = dynamic_cast<mrpt::obs::CObservation2DRangeScan*>(&obs);
	if (!scan) return;
	// The LMS1xx sends its first beam at its start angle (-45 deg in SICK's
	// frame, where 90 deg is ahead: the robot's right) and turns
	// counter-clockwise (SICK's telegram listing; ROS's LMS1xx driver takes
	// the data in that order from angle_min), i.e. right to left.
	scan->rightToLeft = true;
	// No echo is 0 mm on the wire; CLMS100Eth keeps it valid (<= maxRange).
	for (size_t i = 0; i < scan->getScanSize(); i++)
		if (scan->getScanRange(i) <= 0) scan->setScanRangeValidity(i, false);
}

bool DriverQuirks::replaysRecording(
	const std::string& driver, const mrpt::config::CConfigFileBase& cfg, const std::string& section)
{
	// As CCameraSensor::initialize() reads it: trimmed, lower case.
	return driver == "CCameraSensor" &&
		mrpt::system::trim(mrpt::system::lowerCase(
			cfg.read_string_first_word(section, "grabber_type", "opencv"))) == "rawlog";
}
}  // namespace featloc
