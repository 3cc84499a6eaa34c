#pragma once

namespace featloc
{
/** featloc-live: CONFIG [--out DIR] [--duration S] [--set SECTION:KEY=VALUE ...]
 *
 * The same localization as featloc-run, fed by MRPT hardware drivers
 * instead of a file: CONFIG is a featloc ini plus sensor sections in
 * rawlog-grabber's style, `[Live] sensors` picks them (LiveSource). In this
 * order: the configuration (every key checked, the drivers' keys by the
 * drivers), the results folder, the drivers started and each heard from
 * (a silent device is an error within [Live] startup_timeout), then the
 * pipeline until Ctrl-C, SIGTERM or --duration. Everything received is in
 * DIR/live.rawlog, which featloc-run replays to the same poses. */
class LiveApp
{
   public:
	/** Returns the exit code; throws on errors (see guardedMain). */
	int main(int argc, char** argv);
};
}  // namespace featloc
