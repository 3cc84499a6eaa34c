#include "featloc/gui/ViewerFrame.h"

#include <wx/dirdlg.h>
#include <wx/filedlg.h>
#include <wx/utils.h>
#include <wx/menu.h>
#include <wx/msgdlg.h>
#include <wx/notebook.h>
#include <wx/progdlg.h>
#include <wx/sizer.h>
#include <wx/statusbr.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <functional>
#include <iostream>

#include "featloc/core/ExceptionText.h"
#include "featloc/gui/MapCanvas.h"
#include "featloc/gui/MatchPanel.h"
#include "featloc/gui/PlotsPanel.h"
#include "featloc/gui/RawlogRunner.h"
#include "featloc/gui/RunResultsLoader.h"
#include "featloc/gui/StereoPanel.h"
#include "featloc/gui/TimelineBar.h"
#include "featloc/gui/WindowScreenshot.h"

namespace featloc
{
namespace
{
constexpr int kFollowPeriodMs = 1000;
}  // namespace

ViewerFrame::ViewerFrame()
	: wxFrame(nullptr, wxID_ANY, "featloc-viewer", wxDefaultPosition, wxSize(1200, 850))
{
	auto* sizer = new wxBoxSizer(wxVERTICAL);
	m_timeline = new TimelineBar(this);
	m_pages = new wxNotebook(this, wxID_ANY);
	m_map = new MapCanvas(m_pages);
	m_match = new MatchPanel(m_pages);
	m_plots = new PlotsPanel(m_pages);
	m_stereo = new StereoPanel(m_pages);
	m_pages->AddPage(m_map, "Map");
	m_pages->AddPage(m_match, "Match");
	m_pages->AddPage(m_plots, "Plots");
	m_pages->AddPage(m_stereo, "Stereo");
	sizer->Add(m_timeline, 0, wxEXPAND);
	sizer->Add(m_pages, 1, wxEXPAND);
	SetSizer(sizer);
	CreateStatusBar(2);
	const int widths[] = {-1, -2};
	SetStatusWidths(2, widths);
	SetStatusText("open a results folder or a rawlog (File menu)");
	buildMenu();

	m_timeline->onStep = [this](size_t i) { showStep(i); };
	m_plots->onPickStep = [this](size_t i) {
		m_timeline->setStep(i);
		showStep(i);
	};
	m_pages->Bind(wxEVT_NOTEBOOK_PAGE_CHANGED, [this](wxBookCtrlEvent& e) {
		e.Skip();
		if (!m_results.steps.empty()) showStep(m_timeline->step());
	});
	Bind(wxEVT_CHAR_HOOK, &ViewerFrame::onKey, this);
}

void ViewerFrame::buildMenu()
{
	auto* file = new wxMenu;
	auto* bar = new wxMenuBar;
	bar->Append(file, "&File");
	SetMenuBar(bar);
	// A menu item whose action shows its errors in a message box.
	auto item = [&](const wxString& label, std::function<void()> action) {
		const int id = wxWindow::NewControlId();
		file->Append(id, label);
		Bind(
			wxEVT_MENU,
			[this, action](wxCommandEvent&) {
				try
				{
					action();
				}
				catch (const std::exception& e)
				{
					wxMessageBox(exceptionText(e), "featloc-viewer", wxICON_ERROR, this);
				}
			},
			id);
	};
	item("&Open results folder...\tCtrl+O", [this] {
		wxDirDialog dlg(this, "Open a featloc-run results folder");
		if (dlg.ShowModal() == wxID_OK) openResults(dlg.GetPath().ToStdString(), true);
	});
	item("Open &rawlog (runs featloc-run with the defaults)...\tCtrl+R", [this] {
		wxFileDialog dlg(this, "Open a rawlog", "", "",
			"Rawlogs (*.rawlog;*.rawlog.gz;*.log;*.log.gz)|*.rawlog;*.rawlog.gz;*.log;*.log.gz|"
			"All files|*",
			wxFD_OPEN | wxFD_FILE_MUST_EXIST);
		if (dlg.ShowModal() != wxID_OK) return;
		wxBusyCursor busy;
		SetStatusText("running featloc-run on " + dlg.GetPath() + " ...", 0);
		Update();
		openResults(RawlogRunner::run(dlg.GetPath().ToStdString(), ""), true);
	});
	item("Save &screenshot...\tCtrl+S", [this] {
		wxFileDialog dlg(this, "Save a screenshot", "", "featloc-viewer.png", "PNG (*.png)|*.png",
			wxFD_SAVE | wxFD_OVERWRITE_PROMPT);
		if (dlg.ShowModal() == wxID_OK) WindowScreenshot::save(*this, dlg.GetPath().ToStdString());
	});
	file->AppendSeparator();
	file->Append(wxID_EXIT, "&Quit\tCtrl+Q");
	Bind(wxEVT_MENU, [this](wxCommandEvent&) { Close(); }, wxID_EXIT);
}

void ViewerFrame::openResults(const std::string& folder, bool showProgress)
{
	std::unique_ptr<wxProgressDialog> progress;
	if (showProgress)
		progress = std::make_unique<wxProgressDialog>("featloc-viewer", "reading " + folder, 1000, this);
	RunResults loaded = RunResultsLoader::load(folder, [&](double f) {
		if (progress) progress->Update(static_cast<int>(999 * f));
	});
	progress.reset();
	present(std::move(loaded));
	SetTitle("featloc-viewer: " + folder);
	size_t scans = 0;
	for (const auto& s : m_results.steps) scans += s.scan ? 1 : 0;
	SetStatusText(wxString::Format("%zu steps, %zu scans, %zu matches; estimator %s, matcher %s",
					  m_results.steps.size(), scans, m_results.matches.size(),
					  m_results.estimator.empty() ? "?" : m_results.estimator.c_str(),
					  m_results.matcherClass.empty() ? "?" : m_results.matcherClass.c_str()),
		0);
	std::string problems;
	for (const auto& p : m_results.problems)
	{
		std::cerr << "featloc-viewer: " << folder << ": " << p << "\n";
		problems += (problems.empty() ? "" : "; ") + p;
	}
	SetStatusText(problems.empty() ? wxString("every file read") : wxString("not shown: " + problems), 1);
	showStep(0);
}

void ViewerFrame::present(RunResults loaded)
{
	m_results = std::move(loaded);
	m_map->setResults(m_results);
	m_match->setResults(m_results);
	m_plots->setResults(m_results);
	m_stereo->setResults(m_results);
	std::vector<double> times;
	for (const auto& s : m_results.steps) times.push_back(s.t);
	m_timeline->setTimes(times);
}

void ViewerFrame::follow(const std::string& folder)
{
	m_followed = folder;
	m_followTimer.SetOwner(this);
	Bind(wxEVT_TIMER, [this](wxTimerEvent&) { onFollowTimer(); }, m_followTimer.GetId());
	SetStatusText("following " + folder + ": waiting for the run's first step", 0);
	onFollowTimer();
	m_followTimer.Start(kFollowPeriodMs);
}

void ViewerFrame::onFollowTimer()
{
	namespace fs = std::filesystem;
	// The run's staging folder while it runs, the folder once published.
	const fs::path target(m_followed);
	std::string folder = m_followed;
	auto newest = fs::file_time_type::min();  // (libstdc++'s zero is year 2174)
	std::error_code ec;
	const std::string prefix = target.filename().string() + ".featloc-partial-";
	const fs::path parent = target.has_parent_path() ? target.parent_path() : fs::path(".");
	for (const auto& e : fs::directory_iterator(parent, ec))
		if (e.path().filename().string().rfind(prefix, 0) == 0 &&
			fs::exists(e.path() / "poses_cov.txt") && e.last_write_time(ec) >= newest)
		{
			newest = e.last_write_time(ec);
			folder = e.path().string();
		}
	if (!fs::exists(fs::path(folder) / "poses_cov.txt")) return;
	RunResults loaded;
	try
	{
		loaded = RunResultsLoader::load(folder);
	}
	catch (const std::exception&)
	{
		return;	 // the run has not written its first step yet
	}
	const bool grew = loaded.steps.size() != m_results.steps.size() || folder != m_results.folder;
	if (!grew) return;
	const bool atEnd = m_results.steps.empty() || m_timeline->step() + 1 >= m_results.steps.size();
	const size_t keep = m_timeline->step();
	present(std::move(loaded));
	showStep(atEnd ? m_results.steps.size() - 1 : std::min(keep, m_results.steps.size() - 1));
	SetStatusText(wxString::Format("following %s: %zu steps", folder, m_results.steps.size()), 0);
	std::cout << "featloc-viewer: following " << folder << ": " << m_results.steps.size()
			  << " steps" << std::endl;
}

void ViewerFrame::showStep(size_t i)
{
	if (i >= m_results.steps.size()) return;
	m_timeline->setStep(i);
	// Only the visible page is updated while playing: the match page runs
	// the matcher again, which costs as much as the run did.
	switch (static_cast<Page>(m_pages->GetSelection()))
	{
		case Page::Map: m_map->setStep(i); break;
		case Page::Match: m_match->setStep(i); break;
		case Page::Plots: m_plots->setStep(i); break;
		case Page::Stereo: m_stereo->setStep(i); break;
	}
}

double ViewerFrame::measureMapRedraws(unsigned n)
{
	showPage(Page::Map);
	m_map->fitAll();
	m_map->Update();
	const float zoom = m_map->getZoomDistance();
	const auto t0 = std::chrono::steady_clock::now();
	for (unsigned i = 0; i < n; i++)
	{
		m_map->setZoomDistance(zoom * (i % 2 ? 1.01f : 0.99f));
		m_map->Refresh(false);
		m_map->Update();  // paints now: MapCanvas renders and swaps buffers
	}
	return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() /
		std::max(n, 1u);
}

size_t ViewerFrame::step() const { return m_timeline->step(); }
void ViewerFrame::play() { m_timeline->setPlaying(true); }

void ViewerFrame::showPage(Page page) { m_pages->SetSelection(static_cast<size_t>(page)); }

void ViewerFrame::onKey(wxKeyEvent& e)
{
	if (m_results.steps.empty() || wxWindow::FindFocus() == nullptr)
	{
		e.Skip();
		return;
	}
	const auto* focus = wxWindow::FindFocus();
	if (dynamic_cast<const wxTextCtrl*>(focus))  // typing parameters
	{
		e.Skip();
		return;
	}
	const size_t i = m_timeline->step();
	switch (e.GetKeyCode())
	{
		case WXK_SPACE: m_timeline->setPlaying(!m_timeline->playing()); break;
		case WXK_RIGHT: showStep(std::min(i + 1, m_results.steps.size() - 1)); break;
		case WXK_LEFT: showStep(i > 0 ? i - 1 : 0); break;
		default: e.Skip();
	}
}
}  // namespace featloc
