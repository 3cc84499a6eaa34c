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
		" 2>&1 & emu=$!; ";
}

std::string liveArgs(unsigned short laser, unsigned short odo)
{
	return shellQuote(std::string(FEATLOC_SOURCE_DIR) + "/configs/live-emulator.ini") +
		" -q --set LASER:PORT_DIR=" + std::to_string(laser) +
		" --set ODOMETRY:port=" + std::to_string(odo);
}
}  // namespace featloc::test
