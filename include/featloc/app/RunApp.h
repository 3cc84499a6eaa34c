#pragma once

namespace featloc
{
/** featloc-run: CONFIG [RAWLOG] [--out DIR] [--set SECTION:KEY=VALUE ...]
 * Loads the ini (every key checked), runs the pipeline over the rawlog with
 * a progress bar, writes the outputs, prints a summary and, with
 * [Evaluation] ground_truth, the errors against it. */
class RunApp
{
   public:
	/** Returns the exit code; throws on errors (see guardedMain). */
	int main(int argc, char** argv);
};
}  // namespace featloc
