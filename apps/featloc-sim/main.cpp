// featloc-sim: thin entry point; the work is in featloc::SimApp.
#include "featloc/app/AppMain.h"
#include "featloc/app/SimApp.h"

int main(int argc, char** argv)
{
	return featloc::guardedMain(
		"featloc-sim", [&] { return featloc::SimApp().main(argc, argv); });
}
