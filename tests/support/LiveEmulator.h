#pragma once
#include <string>

namespace featloc::test
{
/** Shell text that starts featloc-sim --serve in the background (its pid
 * in $emu): a Hokuyo UTM-30LX at 40 Hz and odometry at 100 Hz driving the
 * office world, its console in PREFIX.out. `extra`: more featloc-sim
 * options. The text goes on once the devices listen (waitForEmulator). */
std::string emulatorCommand(
	const std::string& prefix, unsigned short laser, unsigned short odo,
	const std::string& extra = "");

/** Shell text that waits until the featloc-sim --serve started in the
 * background as $emu, its console in `console`, says its devices listen
 * (or it has ended). */
std::string waitForEmulator(const std::string& console);

/** featloc-live's arguments for that emulator (configs/live-emulator.ini,
 * -q, the two ports). */
std::string liveArgs(unsigned short laser, unsigned short odo);
}  // namespace featloc::test
