#include "featloc/gui/ViewerApp.h"

#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <wx/app.h>
#include <wx/image.h>
#include <wx/init.h>
#include <wx/timer.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <iostream>

#include "featloc/app/AppMain.h"
#include "featloc/app/UsageError.h"
#include "featloc/core/InputError.h"
#include "featloc/gui/MatchPanel.h"
#include "featloc/gui/RawlogRunner.h"
#include "featloc/gui/StereoPanel.h"
#include "featloc/gui/ViewerFrame.h"
#include "featloc/gui/WindowScreenshot.h"

namespace featloc
{
namespace
{
namespace fs = std::filesystem;

// The wx application object: the frame is created by ViewerApp::main.
class WxApp : public wxApp
{
   public:
	bool OnInit() override { return true; }
};

ViewerFrame::Page parsePage(const std::string& name)
{
	if (name == "map") return ViewerFrame::Page::Map;
	if (name == "match") return ViewerFrame::Page::Match;
	if (name == "plots") return ViewerFrame::Page::Plots;
	if (name == "stereo") return ViewerFrame::Page::Stereo;
	throw UsageError("--view must be map, match, plots or stereo, not '" + name + "'");
}
}  // namespace

int ViewerApp::main(int argc, char** argv)
{
	TCLAP::CmdLine cmd(
		"featloc-viewer: look inside featloc runs. INPUT is a featloc-run results folder, or "
		"a rawlog (run through featloc-run first, with --config or the built-in defaults). "
		"Map, match and plot pages over a timeline; Space plays, Left/Right step.",
		' ', "0.1");
	TCLAP::UnlabeledValueArg<std::string> argInput(
		"input", "Results folder or rawlog", false, "", "INPUT", cmd);
	TCLAP::ValueArg<std::string> argConfig(
		"c", "config", "featloc ini for a rawlog INPUT", false, "", "INI", cmd);
	TCLAP::ValueArg<std::string> argShot(
		"", "screenshot", "Save the window as a PNG and exit", false, "", "FILE", cmd);
	TCLAP::ValueArg<size_t> argStep("", "step", "Step to show (0-based)", false, 0, "N", cmd);
	TCLAP::ValueArg<std::string> argView(
		"", "view", "Page to show: map, match, plots or stereo", false, "map", "PAGE", cmd);
	TCLAP::ValueArg<std::string> argRematch("", "rematch",
		"With --view match: re-match the step's pair with this matcher class", false, "", "CLASS",
		cmd);
	TCLAP::MultiArg<std::string> argRematchSet("", "rematch-set",
		"A parameter of the --rematch class, KEY=VALUE as in the ini (repeatable)", false,
		"KEY=VALUE", cmd);
	TCLAP::SwitchArg argPlay("", "play", "Start playing (at the log's own rate)", cmd);
	TCLAP::SwitchArg argFollow("", "follow",
		"INPUT is the results folder of a run in progress (featloc-live, featloc-run): read it "
		"again every second and show the newest step",
		cmd);
	TCLAP::ValueArg<double> argShotAfter("", "screenshot-after",
		"With --screenshot: take it after S seconds (default 0.8)", false, 0.8, "S", cmd);
	TCLAP::ValueArg<unsigned> argRedraws("", "measure-redraws",
		"Redraw the map page N times, print the time per redraw and exit (benchmarks)", false, 0,
		"N", cmd);
	TCLAP::ValueArg<std::string> argSize(
		"", "size", "Window size in pixels", false, "1200x850", "WxH", cmd);
	int exitCode = 0;
	if (!parseCommandLine(cmd, argc, argv, exitCode)) return exitCode;
	const ViewerFrame::Page page = parsePage(argView.getValue());
	int width = 0, height = 0;
	if (std::sscanf(argSize.getValue().c_str(), "%dx%d", &width, &height) != 2 || width < 200 ||
		height < 200)
		throw UsageError("--size must be WxH, at least 200x200, not '" + argSize.getValue() + "'");

	// Everything that can fail is checked before a window opens.
	std::string folder;
	const std::string input = argInput.getValue();
	if (argFollow.getValue())
	{
		// The run may not have created its folder yet.
		if (input.empty()) throw UsageError("--follow needs the run's results folder as INPUT");
		if (fs::exists(input) && !fs::is_directory(input))
			throw UsageError("--follow: '" + input + "' is not a folder");
	}
	else if (!input.empty())
	{
		if (!fs::exists(input)) throw InputError("'" + input + "': no such file or folder");
		folder = fs::is_directory(input) ? input : RawlogRunner::run(input, argConfig.getValue());
	}
	const char* display = std::getenv("DISPLAY");
	const char* wayland = std::getenv("WAYLAND_DISPLAY");
	if ((!display || !*display) && (!wayland || !*wayland))
		throw InputError(
			"featloc-viewer needs a display, and DISPLAY is not set (run it on a desktop, over "
			"ssh -X, or under xvfb-run)");

	wxApp::SetInstance(new WxApp);
	int wxArgc = 1;
	char* wxArgv[] = {argv[0], nullptr};
	if (!wxEntryStart(wxArgc, wxArgv))
		throw InputError(std::string("featloc-viewer cannot open the display '") +
			(display ? display : "") + "' (wxWidgets could not initialise GTK)");
	struct Cleanup
	{
		~Cleanup() { wxEntryCleanup(); }
	} cleanup;
	wxTheApp->CallOnInit();
	wxInitAllImageHandlers();

	auto* frame = new ViewerFrame;
	frame->SetSize(width, height);
	frame->Show();
	const std::string shot = argShot.getValue();
	if (!folder.empty())
	{
		const auto t0 = std::chrono::steady_clock::now();
		frame->openResults(folder, shot.empty() && argRedraws.getValue() == 0);
		size_t scans = 0;
		for (const auto& s : frame->results().steps) scans += s.scan ? 1 : 0;
		std::cout << "featloc-viewer: read " << folder << " in "
				  << std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count()
				  << " s (" << frame->results().steps.size() << " steps, " << scans << " scans)\n";
		if (argStep.getValue() >= frame->results().steps.size())
			throw UsageError("--step " + std::to_string(argStep.getValue()) + ": the run has " +
				std::to_string(frame->results().steps.size()) + " steps");
		frame->showPage(page);
		frame->showStep(argStep.getValue());
		if (!argRematch.getValue().empty())
		{
			std::string params;
			for (const auto& kv : argRematchSet.getValue()) params += kv + "\n";
			frame->matchPanel().setRematchControls(argRematch.getValue(), params);
			frame->matchPanel().rematch();
		}
	}
	if (argFollow.getValue()) frame->follow(input);
	if (argPlay.getValue()) frame->play();
	int result = 0;
	wxTimer timer;
	if (argRedraws.getValue() > 0)
	{
		timer.Bind(wxEVT_TIMER, [&](wxTimerEvent&) {
			const double seconds = frame->measureMapRedraws(argRedraws.getValue());
			std::cout << "featloc-viewer: map redraw " << 1e3 * seconds << " ms on average over "
					  << argRedraws.getValue() << " (" << 1 / seconds << " frames per second)\n";
			frame->Close(true);
		});
		timer.StartOnce(800);
	}
	else if (!shot.empty())
	{
		// Give the window and its GL canvas time to be laid out and drawn.
		timer.Bind(wxEVT_TIMER, [&](wxTimerEvent&) {
			try
			{
				frame->Refresh();
				frame->Update();
				WindowScreenshot::save(*frame, shot);
				std::cout << "featloc-viewer: screenshot " << shot << " (step " << frame->step()
						  << ")\n";
				if (page == ViewerFrame::Page::Match)
					std::cout << frame->matchPanel().summaryText() << "re-matched: "
							  << frame->matchPanel().rematchText() << "\n";
				if (page == ViewerFrame::Page::Stereo)
					std::cout << frame->stereoPanel().summaryText() << "\n";
			}
			catch (const std::exception& e)
			{
				std::cerr << "featloc-viewer: " << e.what() << "\n";
				result = 1;
			}
			frame->Close(true);
		});
		timer.StartOnce(static_cast<int>(1000 * std::max(0.1, argShotAfter.getValue())));
	}
	wxTheApp->OnRun();
	return result;
}
}  // namespace featloc
