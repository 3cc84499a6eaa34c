// featloc-bench-landmarks: thin entry point; the work is in featloc::LandmarkBenchApp.
#include "featloc/app/AppMain.h"
#include "featloc/app/LandmarkBenchApp.h"

int main(int argc, char** argv)
{
	return featloc::guardedMain(
		"featloc-bench-landmarks", [&] { return featloc::LandmarkBenchApp().main(argc, argv); });
}
