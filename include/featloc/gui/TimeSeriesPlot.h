#pragma once
#include <wx/panel.h>

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace featloc
{
/** One plot of featloc-viewer's plots page: a value against time, with an
 * optional band (e.g. NEES's 95% chi-square interval) and a cursor at the
 * current step; clicking picks a time. Drawn with wxDC. */
class TimeSeriesPlot : public wxPanel
{
   public:
	TimeSeriesPlot(wxWindow* parent, std::string title, std::string unit);

	/** Times relative to the run's start [s]. An empty series shows
	 * `emptyText` instead. */
	void setSeries(std::vector<std::pair<double, double>> points, double tEnd,
		const std::string& emptyText);
	void setBand(double low, double high);
	void setCursor(double t);
	/** Called with the time clicked. */
	std::function<void(double)> onPick;

	static constexpr unsigned char kLine[3] = {30, 80, 220};

   private:
	void onPaint(wxPaintEvent&);
	void onClick(wxMouseEvent& e);

	std::string m_title, m_unit, m_emptyText;
	std::vector<std::pair<double, double>> m_points;
	double m_tEnd = 1, m_yMax = 1;
	double m_bandLow = 0, m_bandHigh = -1;	// none while high < low
	double m_cursor = -1;
	int m_left = 60, m_right = 15;	// plot area margins [px]
};
}  // namespace featloc
