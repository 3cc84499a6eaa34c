#pragma once

namespace featloc
{
/** featloc-viewer: opens a featloc-run results folder, or a rawlog (run
 * through featloc-run first, into a temporary folder), in a ViewerFrame.
 * `--screenshot FILE [--step N] [--view map|match|plots]` saves the window
 * as a PNG and exits (the tests and doc/ use it). Without a display it
 * stops with an error saying so. */
class ViewerApp
{
   public:
	int main(int argc, char** argv);
};
}  // namespace featloc
