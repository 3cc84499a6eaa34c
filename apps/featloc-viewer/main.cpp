// featloc-viewer: thin entry point; the work is in featloc::ViewerApp.
#include "featloc/app/AppMain.h"
#include "featloc/gui/ViewerApp.h"

int main(int argc, char** argv)
{
	return featloc::guardedMain(
		"featloc-viewer", [&] { return featloc::ViewerApp().main(argc, argv); });
}
