// featloc-run: thin entry point; the work is in featloc::RunApp.
#include "featloc/app/AppMain.h"
#include "featloc/app/RunApp.h"

int main(int argc, char** argv)
{
	return featloc::guardedMain(
		"featloc-run", [&] { return featloc::RunApp().main(argc, argv); });
}
