// featloc-stereo-import: thin entry point; the work is in featloc::StereoImportApp.
#include "featloc/app/AppMain.h"
#include "featloc/app/StereoImportApp.h"

int main(int argc, char** argv)
{
	return featloc::guardedMain(
		"featloc-stereo-import", [&] { return featloc::StereoImportApp().main(argc, argv); });
}
