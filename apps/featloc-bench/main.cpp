// featloc-bench: thin entry point; the work is in featloc::BenchApp.
#include "featloc/app/AppMain.h"
#include "featloc/app/BenchApp.h"

int main(int argc, char** argv)
{
	return featloc::guardedMain(
		"featloc-bench", [&] { return featloc::BenchApp().main(argc, argv); });
}
