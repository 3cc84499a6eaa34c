#pragma once
#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/obs/CObservation.h>

#include <string>

namespace featloc
{
/** What featloc-live corrects in the observations of MRPT 2.5.8 drivers
 * that misdescribe their device (found by reading the drivers' sources and
 * checked against featloc-sim's device emulator), so that a live run sees
 * the scanner as it is. */
class DriverQuirks
{
   public:
	/** One line for the console when `driver` has corrections, else "". */
	static std::string describe(const std::string& driver);
	/** Corrects an observation of `driver` in place. */
	static void correct(const std::string& driver, mrpt::obs::CObservation& obs);
	/** Whether the driver of `[section]` replays a recording rather than
	 * a device (CCameraSensor with grabber_type = rawlog): it reads as
	 * fast as it is called and keeps the recorded stamps, so featloc-live
	 * paces it (RecordingReplayClock). */
	static bool replaysRecording(const std::string& driver,
		const mrpt::config::CConfigFileBase& cfg, const std::string& section);
};
}  // namespace featloc
