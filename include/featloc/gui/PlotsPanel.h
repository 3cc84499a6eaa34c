#pragma once
#include <wx/panel.h>

#include <functional>

#include "featloc/gui/RunResults.h"

namespace featloc
{
class TimeSeriesPlot;

/** featloc-viewer's plots page: position error against the ground truth
 * (in the estimate's frame, as the ATE), NEES with its 95% chi-square bound
 * (3 dof: 7.815), and time per match, all against time; a cursor follows
 * the current step and a click picks a step. */
class PlotsPanel : public wxPanel
{
   public:
	explicit PlotsPanel(wxWindow* parent);
	void setResults(const RunResults& results);
	void setStep(size_t i);
	std::function<void(size_t)> onPickStep;

	/** Position error of each step against the ground truth (t relative to
	 * the first step [s], error [m]); empty without ground truth. */
	static std::vector<std::pair<double, double>> positionErrors(const RunResults& r);

   private:
	const RunResults* m_results = nullptr;
	TimeSeriesPlot *m_error, *m_nees, *m_time;
};
}  // namespace featloc
