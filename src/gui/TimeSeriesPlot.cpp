#include "featloc/gui/TimeSeriesPlot.h"

#include <wx/dcbuffer.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace featloc
{
namespace
{
// A "nice" tick step (1, 2 or 5 times a power of ten) for about n ticks.
double tickStep(double range, int n)
{
	const double raw = range / std::max(n, 1);
	const double p = std::pow(10.0, std::floor(std::log10(raw)));
	for (double m : {1.0, 2.0, 5.0})
		if (m * p >= raw) return m * p;
	return 10 * p;
}
}  // namespace

TimeSeriesPlot::TimeSeriesPlot(wxWindow* parent, std::string title, std::string unit)
	: wxPanel(parent), m_title(std::move(title)), m_unit(std::move(unit))
{
	SetBackgroundStyle(wxBG_STYLE_PAINT);
	SetMinSize(wxSize(300, 120));
	Bind(wxEVT_PAINT, &TimeSeriesPlot::onPaint, this);
	Bind(wxEVT_LEFT_DOWN, &TimeSeriesPlot::onClick, this);
}

void TimeSeriesPlot::setSeries(
	std::vector<std::pair<double, double>> points, double tEnd, const std::string& emptyText)
{
	m_points = std::move(points);
	m_tEnd = std::max(tEnd, 1e-3);
	m_emptyText = emptyText;
	// The scale leaves out the top 1% so that one outlier does not flatten
	// the rest (points above are drawn at the top edge).
	std::vector<double> v;
	for (const auto& p : m_points)
		if (std::isfinite(p.second)) v.push_back(p.second);
	m_yMax = 1e-9;
	if (!v.empty())
	{
		std::sort(v.begin(), v.end());
		m_yMax = std::max(v[std::min(v.size() - 1, v.size() * 99 / 100)] * 1.1, 1e-9);
	}
	Refresh(false);
}

void TimeSeriesPlot::setBand(double low, double high)
{
	m_bandLow = low;
	m_bandHigh = high;
	m_yMax = std::max(m_yMax, high * 1.2);
	Refresh(false);
}

void TimeSeriesPlot::setCursor(double t)
{
	m_cursor = t;
	Refresh(false);
}

void TimeSeriesPlot::onClick(wxMouseEvent& e)
{
	const int w = GetClientSize().x - m_left - m_right;
	if (!onPick || w <= 0) return;
	onPick(std::clamp((e.GetX() - m_left) / static_cast<double>(w), 0.0, 1.0) * m_tEnd);
}

void TimeSeriesPlot::onPaint(wxPaintEvent&)
{
	wxAutoBufferedPaintDC dc(this);
	dc.SetBackground(*wxWHITE_BRUSH);
	dc.Clear();
	const wxSize size = GetClientSize();
	const int top = 22, bottom = size.y - 22;
	const int left = m_left, right = size.x - m_right;
	dc.SetTextForeground(*wxBLACK);
	dc.DrawText(m_title + " [" + m_unit + "]", left, 3);
	if (right <= left || bottom <= top) return;
	if (m_points.empty())
	{
		dc.DrawText(m_emptyText, left + 10, (top + bottom) / 2);
		return;
	}
	auto X = [&](double t) { return left + static_cast<int>((right - left) * t / m_tEnd); };
	auto Y = [&](double v) {
		return bottom - static_cast<int>((bottom - top) * std::clamp(v / m_yMax, 0.0, 1.0));
	};
	if (m_bandHigh >= m_bandLow)
	{
		dc.SetPen(*wxTRANSPARENT_PEN);
		dc.SetBrush(wxBrush(wxColour(200, 235, 200)));
		dc.DrawRectangle(left, Y(m_bandHigh), right - left, Y(m_bandLow) - Y(m_bandHigh) + 1);
	}
	// Axes with ticks.
	dc.SetPen(wxPen(wxColour(120, 120, 120)));
	dc.DrawLine(left, top, left, bottom);
	dc.DrawLine(left, bottom, right, bottom);
	char label[32];
	const double ys = tickStep(m_yMax, 4);
	for (double v = 0; v <= m_yMax * 1.0001; v += ys)
	{
		dc.DrawLine(left - 4, Y(v), left, Y(v));
		std::snprintf(label, sizeof(label), "%g", v);
		dc.DrawText(label, 4, Y(v) - 7);
	}
	const double ts = tickStep(m_tEnd, 8);
	for (double t = 0; t <= m_tEnd * 1.0001; t += ts)
	{
		dc.DrawLine(X(t), bottom, X(t), bottom + 4);
		std::snprintf(label, sizeof(label), "%g s", t);
		dc.DrawText(label, X(t) - 8, bottom + 5);
	}
	dc.SetPen(wxPen(wxColour(kLine[0], kLine[1], kLine[2]), 1));
	for (size_t i = 1; i < m_points.size(); i++)
		dc.DrawLine(X(m_points[i - 1].first), Y(m_points[i - 1].second), X(m_points[i].first),
			Y(m_points[i].second));
	if (m_points.size() == 1) dc.DrawCircle(X(m_points[0].first), Y(m_points[0].second), 2);
	if (m_cursor >= 0)
	{
		dc.SetPen(wxPen(wxColour(230, 30, 30), 1));
		dc.DrawLine(X(m_cursor), top, X(m_cursor), bottom);
	}
}
}  // namespace featloc
