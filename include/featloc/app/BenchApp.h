#pragma once

namespace featloc
{
/** featloc-bench CONFIG DATA: scan matchers side by side on the scan pairs
 * of a log with Borges & Aldon's perturbed-initial-estimate protocol
 * (ScanPairBenchmark); prints a Markdown table row per matcher. */
class BenchApp
{
   public:
	/** Returns the exit code; throws on errors (see guardedMain). */
	int main(int argc, char** argv);
};
}  // namespace featloc
