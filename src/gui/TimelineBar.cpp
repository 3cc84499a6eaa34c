#include "featloc/gui/TimelineBar.h"

#include <wx/button.h>
#include <wx/choice.h>
#include <wx/sizer.h>
#include <wx/slider.h>
#include <wx/stattext.h>

#include <algorithm>
#include <cstdio>

namespace featloc
{
namespace
{
constexpr int kTickMs = 33;	 // ~30 redraws per second while playing
const double kSpeeds[] = {0.25, 0.5, 1, 2, 5, 10, 50};
}  // namespace

TimelineBar::TimelineBar(wxWindow* parent) : wxPanel(parent), m_timer(this)
{
	auto* sizer = new wxBoxSizer(wxHORIZONTAL);
	m_play = new wxButton(this, wxID_ANY, "Play", wxDefaultPosition, wxSize(70, -1));
	m_speed = new wxChoice(this, wxID_ANY);
	for (double s : kSpeeds) m_speed->Append(wxString::Format("%gx", s));
	m_speed->SetSelection(2);
	m_slider = new wxSlider(this, wxID_ANY, 0, 0, 1);
	m_label = new wxStaticText(this, wxID_ANY, "", wxDefaultPosition, wxSize(230, -1));
	sizer->Add(m_play, 0, wxALL | wxALIGN_CENTER_VERTICAL, 3);
	sizer->Add(m_speed, 0, wxALL | wxALIGN_CENTER_VERTICAL, 3);
	sizer->Add(m_slider, 1, wxALL | wxEXPAND, 3);
	sizer->Add(m_label, 0, wxALL | wxALIGN_CENTER_VERTICAL, 3);
	SetSizer(sizer);
	m_play->Bind(wxEVT_BUTTON, [this](wxCommandEvent&) { setPlaying(!playing()); });
	m_slider->Bind(wxEVT_SLIDER, [this](wxCommandEvent&) {
		m_step = static_cast<size_t>(m_slider->GetValue());
		if (!m_times.empty()) m_playTime = m_times[m_step];
		showLabel();
		if (onStep) onStep(m_step);
	});
	Bind(wxEVT_TIMER, &TimelineBar::onTimer, this);
}

void TimelineBar::setTimes(std::vector<double> times)
{
	m_times = std::move(times);
	m_slider->SetRange(0, std::max<int>(1, static_cast<int>(m_times.size()) - 1));
	setStep(0);
}

void TimelineBar::setStep(size_t i)
{
	if (m_times.empty()) return;
	m_step = std::min(i, m_times.size() - 1);
	m_playTime = m_times[m_step];
	m_slider->SetValue(static_cast<int>(m_step));
	showLabel();
}

void TimelineBar::setPlaying(bool play)
{
	if (play && !m_times.empty())
	{
		if (m_step + 1 >= m_times.size()) setStep(0);
		m_timer.Start(kTickMs);
	}
	else
		m_timer.Stop();
	m_play->SetLabel(playing() ? "Pause" : "Play");
}

void TimelineBar::onTimer(wxTimerEvent&)
{
	m_playTime += kTickMs * 1e-3 * kSpeeds[std::max(0, m_speed->GetSelection())];
	size_t i = m_step;
	while (i + 1 < m_times.size() && m_times[i + 1] <= m_playTime) i++;
	if (i + 1 >= m_times.size()) setPlaying(false);
	if (i == m_step) return;
	m_step = i;
	m_slider->SetValue(static_cast<int>(m_step));
	showLabel();
	if (onStep) onStep(m_step);
}

void TimelineBar::showLabel()
{
	if (m_times.empty()) return;
	m_label->SetLabel(wxString::Format("step %zu / %zu   t = %.2f s", m_step, m_times.size() - 1,
		m_times[m_step] - m_times.front()));
}
}  // namespace featloc
