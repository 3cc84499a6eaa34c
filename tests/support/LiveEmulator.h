#pragma once
#include <string>

namespace featloc::test
{
/** Shell text that starts featloc-sim --serve in the background (its pid
 * in $emu): a Hokuyo UTM-30LX at 40 Hz and odometry at 100 Hz driving the
 * office world, its console in PREFIX.out. `extra`: more featloc-sim
 * options. */
std::string emulatorCommand(
	const std::string& prefix, unsigned short laser, unsigned short odo,
	const std::string& extra = "");

/** featloc-live's arguments for that emulator (configs/live-emulator.ini,
 * -q, the two ports). */
std::string liveArgs(unsigned short laser, unsigned short odo);
}  // namespace featloc::test
