#pragma once
#include <wx/panel.h>

#include <string>

#include "featloc/gui/RunResults.h"
#include "featloc/matchers/MatchResult.h"

class wxChoice;
class wxTextCtrl;

namespace featloc
{
class ScanPairPanel;

/** featloc-viewer's match page for the current step: what the run's
 * matcher did (matches.txt: status, iterations, time, covariance, the
 * failure or gate reason), drawn with what it used (the matcher is run
 * again on the same pair with the run's config and guess, and asked
 * through ScanMatcher::inspectLastMatch), and, side by side, the same pair
 * re-matched with another class or parameters (ini names, `key = value`
 * per line, over the run's config). */
class MatchPanel : public wxPanel
{
   public:
	explicit MatchPanel(wxWindow* parent);
	void setResults(const RunResults& results);
	void setStep(size_t i);
	/** Re-matches the current pair with the class and parameters in the
	 * controls (what the "Re-match" button does). */
	void rematch();
	/** Sets the re-match controls: a class name and `key = value` lines. */
	void setRematchControls(const std::string& className, const std::string& params);
	/** The texts shown for the run's match and for the re-match. */
	std::string summaryText() const;
	std::string rematchText() const;

   private:
	/** Runs the matcher made from the run's config plus `overrides` on the
	 * current pair; fills `panel` and returns a description. */
	std::string runMatcher(const std::string& className, const std::string& overrides,
		ScanPairPanel& panel, const std::string& caption) const;

	const RunResults* m_results = nullptr;
	std::string m_configText;  //!< the run's config_used.ini, read once
	size_t m_step = 0;
	wxTextCtrl *m_info, *m_rerunInfo, *m_params;
	wxChoice* m_class;
	ScanPairPanel *m_run, *m_rerun;
};
}  // namespace featloc
