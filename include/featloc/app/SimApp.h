#pragma once

namespace featloc
{
/** featloc-sim WORLD.ini|yaml --out PREFIX [--seed N] [--set ...]: writes
 * PREFIX.rawlog, PREFIX.gt.txt (true robot pose at every scan, TUM) and
 * PREFIX.3Dscene (the world) and PREFIX.png (a top view). */
class SimApp
{
   public:
	/** Returns the exit code; throws on errors (see guardedMain). */
	int main(int argc, char** argv);
};
}  // namespace featloc
