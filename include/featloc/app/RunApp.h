#pragma once

namespace featloc
{
/** featloc-run: CONFIG [INPUT] [--out DIR] [--set SECTION:KEY=VALUE ...]
 *
 * In this order, so that nothing is written before everything is known to
 * be usable: parse the command line (unknown options are usage errors);
 * load the ini (every key checked); open the input (a rawlog or a CARMEN
 * log: its first entry is read) and the ground truth (read whole); check the
 * results folder. Then run the pipeline into a staging folder with a
 * progress line (Ctrl-C stops cleanly), evaluate against the ground truth,
 * publish the staging folder as the results folder, and print a summary. */
class RunApp
{
   public:
	/** Returns the exit code; throws on errors (see guardedMain). */
	int main(int argc, char** argv);
};
}  // namespace featloc
