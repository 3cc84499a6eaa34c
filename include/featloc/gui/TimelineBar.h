#pragma once
#include <wx/panel.h>
#include <wx/timer.h>

#include <functional>
#include <vector>

class wxSlider;
class wxButton;
class wxChoice;
class wxStaticText;

namespace featloc
{
/** featloc-viewer's timeline: a slider over the steps, play/pause, and the
 * playback speed (times the log's own rate). Playing advances by the log's
 * times, so a 10 Hz log plays at 10 steps per second at 1x. */
class TimelineBar : public wxPanel
{
   public:
	explicit TimelineBar(wxWindow* parent);
	/** Step times [s] (sorted). */
	void setTimes(std::vector<double> times);
	void setStep(size_t i);	 //!< moves the slider without calling onStep
	size_t step() const { return m_step; }
	void setPlaying(bool playing);
	bool playing() const { return m_timer.IsRunning(); }
	std::function<void(size_t)> onStep;

   private:
	void onTimer(wxTimerEvent&);
	void showLabel();

	wxSlider* m_slider;
	wxButton* m_play;
	wxChoice* m_speed;
	wxStaticText* m_label;
	wxTimer m_timer;
	std::vector<double> m_times;
	size_t m_step = 0;
	double m_playTime = 0;	// log time being shown while playing [s]
};
}  // namespace featloc
