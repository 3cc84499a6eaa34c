#pragma once
#include <wx/frame.h>
#include <wx/timer.h>

#include <string>

#include "featloc/gui/RunResults.h"

class wxNotebook;

namespace featloc
{
class MapCanvas;
class MatchPanel;
class PlotsPanel;
class StereoPanel;
class TimelineBar;

/** featloc-viewer's main window: a timeline over the run's steps and three
 * pages, the map (MapCanvas), the current match (MatchPanel), the plots
 * (PlotsPanel) and the stereo pair (StereoPanel). Space plays or pauses, Left/Right step. */
class ViewerFrame : public wxFrame
{
   public:
	enum class Page
	{
		Map = 0,
		Match = 1,
		Plots = 2,
		Stereo = 3
	};

	ViewerFrame();
	/** Loads a results folder (RunResultsLoader); throws InputError when it
	 * is not one. Problems with single files are shown in the status bar
	 * and printed on stderr. */
	void openResults(const std::string& folder, bool showProgress);
	void showStep(size_t i);
	size_t step() const;  //!< the step shown
	void play();  //!< what the Play button does
	/** Follows a run in progress: every second, reads the newest
	 * `folder.featloc-partial-PID` staging folder (where featloc-run and
	 * featloc-live write until they finish), else `folder`, and shows the
	 * latest step when there are new ones. */
	void follow(const std::string& folder);
	void showPage(Page page);
	const RunResults& results() const { return m_results; }
	/** Shows the map page and redraws it `n` times, each with a slightly
	 * different zoom (so nothing can be reused), each drawn to the screen
	 * before the next; returns the mean seconds per redraw. */
	double measureMapRedraws(unsigned n);
	MatchPanel& matchPanel() { return *m_match; }
	const StereoPanel& stereoPanel() const { return *m_stereo; }

   private:
	void buildMenu();
	void onKey(wxKeyEvent& e);

	/** Shows `loaded` on every page, the timeline at its start. */
	void present(RunResults loaded);
	void onFollowTimer();

	RunResults m_results;
	std::string m_followed;
	wxTimer m_followTimer;
	TimelineBar* m_timeline;
	wxNotebook* m_pages;
	MapCanvas* m_map;
	MatchPanel* m_match;
	PlotsPanel* m_plots;
	StereoPanel* m_stereo;
};
}  // namespace featloc
