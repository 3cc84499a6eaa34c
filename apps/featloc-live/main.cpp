// featloc-live: thin entry point; the work is in featloc::LiveApp.
#include "featloc/app/AppMain.h"
#include "featloc/app/LiveApp.h"

int main(int argc, char** argv)
{
	return featloc::guardedMain(
		"featloc-live", [&] { return featloc::LiveApp().main(argc, argv); });
}
