// featloc-eval: thin entry point; the work is in featloc::EvalApp.
#include "featloc/app/AppMain.h"
#include "featloc/app/EvalApp.h"

int main(int argc, char** argv)
{
	return featloc::guardedMain(
		"featloc-eval", [&] { return featloc::EvalApp().main(argc, argv); });
}
