#include "featloc/gui/PlotsPanel.h"

#include <mrpt/poses/CPose2D.h>
#include <wx/sizer.h>

#include <cmath>

#include "featloc/eval/TrajectoryEvaluator.h"
#include "featloc/gui/TimeSeriesPlot.h"

namespace featloc
{
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
	// The steps paired with the ground truth as featloc-run paired them for
	// its ATE (TrajectoryEvaluator, the run's max_time_difference).
	Trajectory estimate;
	for (const auto& s : r.steps)
	{
		estimate.repeatedTimes |= !estimate.poses.empty() && estimate.poses.back().t == s.t;
		TimedPose p;
		p.t = s.t;
		p.pose = s.pose;
		estimate.poses.push_back(p);
	}
	std::vector<std::pair<size_t, size_t>> pairs;
	try
	{
		pairs = TrajectoryEvaluator(r.maxTimeDifference).associate(*r.groundTruth, estimate);
	}
	catch (const std::exception&)
	{
		return out;	 // times that cannot be paired: no plot (the run said why)
	}
	const mrpt::poses::CPose2D toEstimate(r.groundTruthToEstimate);
	for (const auto& [g, e] : pairs)
	{
		const mrpt::poses::CPose2D ref =
			toEstimate + mrpt::poses::CPose2D(r.groundTruth->poses[g].pose);
		const auto& s = r.steps[e];
		out.emplace_back(s.t - r.steps[0].t, std::hypot(ref.x() - s.pose.x, ref.y() - s.pose.y));
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
	m_nees->setBand(0, EvaluationReport::kNeesBound95);
	m_time->setSeries(std::move(times), tEnd, "no scan matches in this run");
}

void PlotsPanel::setStep(size_t i)
{
	if (!m_results || i >= m_results->steps.size()) return;
	const double t = m_results->steps[i].t - m_results->steps[0].t;
	for (TimeSeriesPlot* p : {m_error, m_nees, m_time}) p->setCursor(t);
}
}  // namespace featloc
