#include "support/LiveEmulator.h"

#include "support/CommandRunner.h"

namespace featloc::test
{
std::string emulatorCommand(
	const std::string& prefix, unsigned short laser, unsigned short odo, const std::string& extra)
{
	return shellQuote(FEATLOC_SIM_EXE) + " " +
		shellQuote(std::string(FEATLOC_SOURCE_DIR) + "/worlds/office.ini") + " --out " +
		shellQuote(prefix) + " --serve -q --laser-port " + std::to_string(laser) +
		" --odometry-port " + std::to_string(odo) +
		" --set Laser:preset=hokuyo_utm30lx --set Laser:rate=40 --set Odometry:rate=100"
		" --set Simulation:duration=40 " + extra + " > " + shellQuote(prefix + ".out") +
		" 2>&1 & emu=$!; " + waitForEmulator(prefix + ".out");
}

std::string waitForEmulator(const std::string& console)
{
	// featloc-sim simulates the whole log before it opens its ports, which
	// takes longer than any fixed sleep when ctest loads both cores; it
	// prints this line once every device listens. Up to 60 s, and not
	// past the emulator's end (a bad option).
	return "i=0; while [ $i -lt 600 ] && kill -0 $emu 2>/dev/null && ! grep -q "
		   "'waiting for the drivers to connect' " +
		shellQuote(console) + " 2>/dev/null; do sleep 0.1; i=$((i+1)); done; ";
}

std::string liveArgs(unsigned short laser, unsigned short odo)
{
	return shellQuote(std::string(FEATLOC_SOURCE_DIR) + "/configs/live-emulator.ini") +
		" -q --set LASER:PORT_DIR=" + std::to_string(laser) +
		" --set ODOMETRY:port=" + std::to_string(odo);
}
}  // namespace featloc::test
