#pragma once

namespace featloc
{
/** featloc-eval REFERENCE ESTIMATE [--plot FILE.png] [--json]: ATE and RPE
 * of a trajectory against a reference trajectory, or relation errors
 * against a Kummerle et al. relations file. */
class EvalApp
{
   public:
	/** Returns the exit code; throws on errors (see guardedMain). */
	int main(int argc, char** argv);
};
}  // namespace featloc
