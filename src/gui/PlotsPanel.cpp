#include "featloc/gui/PlotsPanel.h"

#include <mrpt/poses/CPose2D.h>
#include <wx/sizer.h>

#include <cmath>

#include "featloc/gui/TimeSeriesPlot.h"

namespace featloc
{
namespace
{
// The 95% quantile of chi-square with 3 degrees of freedom, the bound
// featloc-run's NEES figure uses.
constexpr double kChi2_3dof_95 = 7.815;
// Ground truth further than this from a step's time is not paired with it.
constexpr double kMaxPairingGap = 0.05;	 // [s]
}  // namespace

PlotsPanel::PlotsPanel(wxWindow* parent) : wxPanel(parent)
{
	auto* sizer = new wxBoxSizer(wxVERTICAL);
	m_error = new TimeSeriesPlot(this, "position error against the ground truth", "m");
	m_nees = new TimeSeriesPlot(this, "NEES (3 dof), green: 95% chi-square bound", "-");
	m_time = new TimeSeriesPlot(this, "time per match", "ms");
	for (TimeSeriesPlot* p : {m_error, m_nees, m_time})
	{
		sizer->Add(p, 1, wxEXPAND | wxALL, 2);
		p->onPick = [this](double t) {
			if (m_results && onPickStep) onPickStep(m_results->stepNearest(m_results->steps[0].t + t));
		};
	}
	SetSizer(sizer);
}

std::vector<std::pair<double, double>> PlotsPanel::positionErrors(const RunResults& r)
{
	std::vector<std::pair<double, double>> out;
	if (!r.groundTruth || r.steps.empty()) return out;
	const auto& gt = r.groundTruth->poses;
	const mrpt::poses::CPose2D toEstimate(r.groundTruthToEstimate);
	const double t0 = r.steps[0].t;
	for (size_t i = 0; i < r.steps.size(); i++)
	{
		const auto& s = r.steps[i];
		const TimedPose* ref = nullptr;
		if (!r.groundTruth->timed)
			ref = i < gt.size() ? &gt[i] : nullptr;	// untimed: paired in order
		else
		{
			auto it = std::lower_bound(gt.begin(), gt.end(), s.t,
				[](const TimedPose& p, double t) { return p.t < t; });
			if (it != gt.begin() && (it == gt.end() || std::abs((it - 1)->t - s.t) < std::abs(it->t - s.t)))
				--it;
			if (it != gt.end() && std::abs(it->t - s.t) <= kMaxPairingGap) ref = &*it;
		}
		if (!ref) continue;
		const mrpt::poses::CPose2D g = toEstimate + mrpt::poses::CPose2D(ref->pose);
		out.emplace_back(s.t - t0, std::hypot(g.x() - s.pose.x, g.y() - s.pose.y));
	}
	return out;
}

void PlotsPanel::setResults(const RunResults& r)
{
	m_results = &r;
	const double t0 = r.steps.front().t, tEnd = r.steps.back().t - t0;
	m_error->setSeries(positionErrors(r), tEnd,
		r.groundTruth ? "no step pairs with the ground truth's times"
					  : "no ground truth (set [Evaluation] ground_truth in the run's config)");
	std::vector<std::pair<double, double>> nees, times;
	for (const auto& [t, v] : r.nees) nees.emplace_back(t - t0, v);
	for (const auto& m : r.matches) times.emplace_back(m.t - t0, m.timeMs);
	m_nees->setSeries(std::move(nees), tEnd,
		r.groundTruth ? "nees.txt is missing" : "no ground truth: no NEES");
	m_nees->setBand(0, kChi2_3dof_95);
	m_time->setSeries(std::move(times), tEnd, "no scan matches in this run");
}

void PlotsPanel::setStep(size_t i)
{
	if (!m_results || i >= m_results->steps.size()) return;
	const double t = m_results->steps[i].t - m_results->steps[0].t;
	for (TimeSeriesPlot* p : {m_error, m_nees, m_time}) p->setCursor(t);
}
}  // namespace featloc
