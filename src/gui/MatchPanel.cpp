#include "featloc/gui/MatchPanel.h"

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose3D.h>
#include <wx/button.h>
#include <wx/choice.h>
#include <wx/sizer.h>
#include <wx/splitter.h>
#include <wx/stattext.h>
#include <wx/textctrl.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <sstream>
#include <vector>

#include "featloc/app/UsageError.h"
#include "featloc/config/TrackedConfig.h"
#include "featloc/gui/ScanPairPanel.h"
#include "featloc/matchers/ScanMatcherFactory.h"
#include "featloc/scan/ScanPoints.h"

namespace featloc
{
namespace
{
std::string describeMotion(const mrpt::math::TPose2D& p)
{
	char buf[96];
	std::snprintf(buf, sizeof(buf), "x %.3f m, y %.3f m, yaw %.2f deg", p.x, p.y,
		mrpt::RAD2DEG(p.phi));
	return buf;
}

std::string describeSigmas(const mrpt::math::CMatrixDouble33& c)
{
	char buf[96];
	std::snprintf(buf, sizeof(buf), "sigma x %.1f mm, y %.1f mm, yaw %.3f deg",
		1e3 * std::sqrt(std::max(c(0, 0), 0.0)), 1e3 * std::sqrt(std::max(c(1, 1), 0.0)),
		mrpt::RAD2DEG(std::sqrt(std::max(c(2, 2), 0.0))));
	return buf;
}

mrpt::poses::CPose2D planarSensorPose(const mrpt::obs::CObservation2DRangeScan& s)
{
	return mrpt::poses::CPose2D(mrpt::poses::CPose3D(s.sensorPose));
}
}  // namespace

MatchPanel::MatchPanel(wxWindow* parent) : wxPanel(parent)
{
	auto* sizer = new wxBoxSizer(wxVERTICAL);
	auto* views = new wxBoxSizer(wxHORIZONTAL);
	auto* left = new wxBoxSizer(wxVERTICAL);
	auto* right = new wxBoxSizer(wxVERTICAL);
	m_run = new ScanPairPanel(this, "the run's match");
	m_info = new wxTextCtrl(this, wxID_ANY, "", wxDefaultPosition, wxSize(-1, 200),
		wxTE_MULTILINE | wxTE_READONLY | wxTE_DONTWRAP);
	left->Add(m_run, 1, wxEXPAND | wxALL, 2);
	left->Add(m_info, 0, wxEXPAND | wxALL, 2);

	m_rerun = new ScanPairPanel(this, "re-matched");
	auto* controls = new wxBoxSizer(wxHORIZONTAL);
	m_class = new wxChoice(this, wxID_ANY);
	for (const auto& name : ScanMatcherFactory::knownClassNames()) m_class->Append(name);
	m_params = new wxTextCtrl(this, wxID_ANY, "", wxDefaultPosition, wxSize(-1, 50),
		wxTE_MULTILINE);
	m_params->SetHint("key = value (one per line, as in the ini)");
	auto* button = new wxButton(this, wxID_ANY, "Re-match");
	controls->Add(m_class, 0, wxALL | wxALIGN_TOP, 2);
	controls->Add(m_params, 1, wxALL | wxEXPAND, 2);
	controls->Add(button, 0, wxALL | wxALIGN_TOP, 2);
	m_rerunInfo = new wxTextCtrl(this, wxID_ANY, "", wxDefaultPosition, wxSize(-1, 145),
		wxTE_MULTILINE | wxTE_READONLY | wxTE_DONTWRAP);
	right->Add(m_rerun, 1, wxEXPAND | wxALL, 2);
	right->Add(controls, 0, wxEXPAND);
	right->Add(m_rerunInfo, 0, wxEXPAND | wxALL, 2);
	views->Add(left, 1, wxEXPAND);
	views->Add(right, 1, wxEXPAND);
	sizer->Add(views, 1, wxEXPAND);
	SetSizer(sizer);
	button->Bind(wxEVT_BUTTON, [this](wxCommandEvent&) { rematch(); });
}

void MatchPanel::setResults(const RunResults& results)
{
	m_results = &results;
	m_configText.clear();
	if (!results.configPath.empty())
	{
		std::ifstream in(results.configPath);
		m_configText.assign(std::istreambuf_iterator<char>(in), {});
	}
	const int i = m_class->FindString(results.matcherClass);
	m_class->SetSelection(i == wxNOT_FOUND ? 0 : i);
	setStep(0);
}

std::string MatchPanel::runMatcher(const std::string& className, const std::string& overrides,
	ScanPairPanel& panel, const std::string& caption) const
{
	const auto& step = m_results->steps[m_step];
	const auto& row = m_results->matches[static_cast<size_t>(step.match)];
	const auto& ref = m_results->steps[static_cast<size_t>(step.reference)];
	// The run's configuration with the class and the overrides applied as
	// --set would apply them; TrackedConfig then names any key the matcher
	// does not read (a typo, with "did you mean"), as featloc-run does.
	TrackedConfig cfg;
	cfg.loadText(m_configText, m_results->configPath.empty() ? "(built-in defaults)"
															 : m_results->configPath);
	cfg.applyOverride(std::string(ScanMatcherFactory::kSection) + ":class=" + className);
	const std::string section = ScanMatcherFactory::paramsSection(className);
	std::istringstream lines(overrides);
	for (std::string line; std::getline(lines, line);)
	{
		if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
		if (line.find('=') == std::string::npos)
			throw std::runtime_error("'" + line + "' is not 'key = value'");
		cfg.applyOverride(section + ":" + line);
	}
	auto matcher = ScanMatcherFactory::createFromConfig(cfg);
	std::vector<std::string> sections;
	cfg.getAllSections(sections);
	for (const auto& other : sections)	// the rest of the run's configuration
		if (other != section) cfg.acceptSection(other);
	cfg.requireAllKeysRead();
	const mrpt::poses::CPosePDFGaussian guess(mrpt::poses::CPose2D(row.guess), row.guessCov);
	const MatchResult r = matcher->match(*ref.scan, *step.scan, guess, row.gateAllowance);
	const mrpt::poses::CPose2D sensorEstimate = (mrpt::poses::CPose2D() - planarSensorPose(*ref.scan)) +
		r.estimate.mean + planarSensorPose(*step.scan);
	MatchInspection used = matcher->inspectLastMatch(
		ScanPoints::fromScan(*ref.scan), ScanPoints::fromScan(*step.scan), sensorEstimate);
	size_t kept = 0;
	for (const auto& part : used.parts) kept += part.kept ? 1 : 0;
	std::ostringstream usedOut;
	usedOut << "what it used: " << used.pairs.size() << " pairs (" << used.pairsDescription << ")";
	if (!used.parts.empty())
		usedOut << "; " << kept << " of " << used.parts.size() << " lines, clusters or segments kept";
	usedOut << "\n";
	for (const auto& part : used.parts)
		if (!part.kept)
			usedOut << "  dropped " << (part.current ? "current " : "reference ") << part.kind << " ("
					<< part.points.size() << " points): " << part.note << "\n";
	const std::string usedText = usedOut.str();
	panel.setMatch(ref.scan, step.scan, r.estimate.mean.asTPose(), std::move(used), caption);
	std::ostringstream out;
	out << className << ": "
		<< (r.success ? (r.guessGateOverruled.empty() ? "success" : "success, guess gate overruled")
					  : r.rejectedByGuessGate ? "rejected by the guess gate"
											  : "failed")
		<< (r.success && !r.primaryFailure.empty()
				   ? " by its fallback " + matcher->fallback()->className()
				   : std::string())
		<< ", " << r.iterations << " iterations, " << r.timeSeconds * 1e3 << " ms\n"
		<< "estimate: " << describeMotion(r.estimate.mean.asTPose()) << "\n"
		<< "covariance: " << describeSigmas(r.estimate.cov) << "\n";
	if (!r.success) out << "reason: " << r.failureReason << "\n";
	if (!r.guessGateOverruled.empty()) out << "guess gate: " << r.guessGateOverruled << "\n";
	if (r.success && !r.primaryFailure.empty())
		out << "fallback_class took over after " << r.primaryFailure << "\n";
	return out.str() + usedText;
}

void MatchPanel::setStep(size_t i)
{
	if (!m_results || i >= m_results->steps.size()) return;
	m_step = i;
	const auto& step = m_results->steps[i];
	m_rerun->clear("choose a class or parameters and press Re-match");
	m_rerunInfo->Clear();
	if (step.match < 0)
	{
		m_run->clear(m_results->matches.empty() ? "this run has no scan matches (matches.txt)"
												: "no match at this step");
		m_info->SetValue(wxString::Format("step %zu: no match", i));
		return;
	}
	const auto& row = m_results->matches[static_cast<size_t>(step.match)];
	std::ostringstream info;
	info << "step " << i << " (t = " << step.t - m_results->steps[0].t << " s), reference step "
		 << step.reference << "\n"
		 << "status: " << row.status << (row.used ? ", used by the estimator" : ", NOT used")
		 << "; " << row.iterations << " iterations, " << row.timeMs << " ms, goodness "
		 << row.goodness << ", points " << row.referencePoints << " / " << row.currentPoints << "\n"
		 << "guess:    " << describeMotion(row.guess) << "\n"
		 << "estimate: " << describeMotion(row.estimate) << "\n"
		 << "covariance: " << describeSigmas(row.cov) << "\n";
	if (!row.reason.empty()) info << "reason: " << row.reason << "\n";
	if (!step.scan || step.reference < 0 || !m_results->steps[step.reference].scan)
	{
		m_run->clear("the scans of this pair are not in estimated.rawlog");
		m_info->SetValue(info.str());
		return;
	}
	try
	{
		const std::string again = runMatcher(m_results->matcherClass, "", *m_run,
			"drawn from the run's matcher run again on this pair");
		info << "run again here: " << again;
	}
	catch (const std::exception& e)
	{
		m_run->clear(std::string("cannot run the matcher again: ") + e.what());
	}
	m_info->SetValue(info.str());
}

void MatchPanel::rematch()
{
	if (!m_results || m_results->steps.empty()) return;
	const auto& step = m_results->steps[m_step];
	if (step.match < 0 || step.reference < 0 || !step.scan ||
		!m_results->steps[step.reference].scan)
	{
		m_rerunInfo->SetValue("no match at this step to re-run");
		return;
	}
	const std::string cls = m_class->GetStringSelection().ToStdString();
	try
	{
		m_rerunInfo->SetValue(runMatcher(cls, m_params->GetValue().ToStdString(), *m_rerun,
			cls + " with the run's config and the parameters above"));
	}
	catch (const std::exception& e)
	{
		m_rerun->clear("not re-matched");
		m_rerunInfo->SetValue(std::string("error: ") + e.what());
	}
}

void MatchPanel::setRematchControls(const std::string& className, const std::string& params)
{
	const std::string name =
		className.find("::") == std::string::npos ? "featloc::" + className : className;
	const int i = m_class->FindString(name);
	if (i == wxNOT_FOUND)
	{
		std::string known;
		for (const auto& n : ScanMatcherFactory::knownClassNames())
			known += (known.empty() ? "" : ", ") + n;
		throw UsageError("--rematch: no matcher class '" + className + "' (known: " + known + ")");
	}
	m_class->SetSelection(i);
	m_params->SetValue(params);
}

std::string MatchPanel::summaryText() const { return m_info->GetValue().ToStdString(); }
std::string MatchPanel::rematchText() const { return m_rerunInfo->GetValue().ToStdString(); }
}  // namespace featloc
