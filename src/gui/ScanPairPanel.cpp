#include "featloc/gui/ScanPairPanel.h"

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPose3D.h>
#include <wx/dcbuffer.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "featloc/scan/ScanPoints.h"

namespace featloc
{
namespace
{
mrpt::poses::CPose2D sensorPose(const mrpt::obs::CObservation2DRangeScan& scan)
{
	return mrpt::poses::CPose2D(mrpt::poses::CPose3D(scan.sensorPose));
}

wxColour rgb(const unsigned char (&c)[3]) { return wxColour(c[0], c[1], c[2]); }
}  // namespace

ScanPairPanel::ScanPairPanel(wxWindow* parent, std::string title)
	: wxPanel(parent), m_title(std::move(title))
{
	SetBackgroundStyle(wxBG_STYLE_PAINT);
	SetMinSize(wxSize(250, 250));
	Bind(wxEVT_PAINT, &ScanPairPanel::onPaint, this);
}

void ScanPairPanel::setMatch(std::shared_ptr<mrpt::obs::CObservation2DRangeScan> reference,
	std::shared_ptr<mrpt::obs::CObservation2DRangeScan> current,
	const mrpt::math::TPose2D& estimate, MatchInspection inspection, const std::string& caption)
{
	m_reference = std::move(reference);
	m_current = std::move(current);
	m_estimate = estimate;
	m_inspection = std::move(inspection);
	m_caption = caption;
	m_message.clear();
	Refresh(false);
}

void ScanPairPanel::clear(const std::string& message)
{
	m_reference.reset();
	m_current.reset();
	m_message = message;
	Refresh(false);
}

void ScanPairPanel::onPaint(wxPaintEvent&)
{
	wxAutoBufferedPaintDC dc(this);
	dc.SetBackground(*wxWHITE_BRUSH);
	dc.Clear();
	dc.SetTextForeground(*wxBLACK);
	dc.DrawText(m_title, 5, 3);
	const wxSize size = GetClientSize();
	if (!m_reference || !m_current)
	{
		dc.DrawText(m_message, 10, size.y / 2);
		return;
	}
	// Everything in the reference robot frame: reference items through
	// its sensor pose S1, current items through X (+) S2.
	const mrpt::poses::CPose2D toRef = sensorPose(*m_reference);
	const mrpt::poses::CPose2D toCur = mrpt::poses::CPose2D(m_estimate) + sensorPose(*m_current);
	auto place = [](const mrpt::poses::CPose2D& T, const mrpt::math::TPoint2D& p) {
		double x, y;
		T.composePoint(p.x, p.y, x, y);
		return mrpt::math::TPoint2D(x, y);
	};
	std::vector<mrpt::math::TPoint2D> ref, cur;
	for (const auto& p : ScanPoints::fromScan(*m_reference).points)
		ref.push_back(place(toRef, {p.x, p.y}));
	for (const auto& p : ScanPoints::fromScan(*m_current).points)
		cur.push_back(place(toCur, {p.x, p.y}));

	double minX = -1, maxX = 1, minY = -1, maxY = 1;
	for (const auto* v : {&ref, &cur})
		for (const auto& p : *v)
		{
			minX = std::min(minX, p.x), maxX = std::max(maxX, p.x);
			minY = std::min(minY, p.y), maxY = std::max(maxY, p.y);
		}
	const int top = 22, bottom = size.y - 60;
	const double scale =
		0.95 * std::min(size.x / (maxX - minX), std::max(bottom - top, 10) / (maxY - minY));
	const double cx = 0.5 * (minX + maxX), cy = 0.5 * (minY + maxY);
	auto P = [&](const mrpt::math::TPoint2D& p) {
		return wxPoint(static_cast<int>(size.x / 2 + (p.x - cx) * scale),
			static_cast<int>((top + bottom) / 2 - (p.y - cy) * scale));
	};

	dc.SetPen(wxPen(wxColour(190, 190, 190), 1));
	for (const auto& pr : m_inspection.pairs)
		dc.DrawLine(P(place(toRef, pr.reference)), P(place(toCur, pr.current)));
	auto drawPoints = [&](const std::vector<mrpt::math::TPoint2D>& pts, const unsigned char (&c)[3]) {
		dc.SetPen(wxPen(rgb(c), 1));
		dc.SetBrush(wxBrush(rgb(c)));
		for (const auto& p : pts) dc.DrawRectangle(P(p) - wxPoint(1, 1), wxSize(3, 3));
	};
	drawPoints(ref, kReference);
	drawPoints(cur, kCurrent);
	// Over the points: what the matcher kept (a thin dark line along each
	// part) and, in orange, what it dropped, which is what one looks for.
	for (const auto& part : m_inspection.parts)
	{
		const auto& T = part.current ? toCur : toRef;
		dc.SetPen(part.kept ? wxPen(wxColour(60, 60, 60), 1) : wxPen(rgb(kDropped), 4));
		for (size_t i = 1; i < part.points.size(); i++)
			dc.DrawLine(P(place(T, part.points[i - 1])), P(place(T, part.points[i])));
		if (!part.kept && part.points.size() == 1)
			dc.DrawCircle(P(place(T, part.points[0])), 4);
	}
	// 1 m scale bar.
	dc.SetPen(wxPen(*wxBLACK, 2));
	dc.DrawLine(10, bottom + 8, 10 + static_cast<int>(scale), bottom + 8);
	dc.DrawText("1 m", 14 + static_cast<int>(scale), bottom + 1);

	size_t dropped = 0;
	for (const auto& part : m_inspection.parts) dropped += part.kept ? 0 : 1;
	std::ostringstream legend;
	legend << "cyan: reference, red: current at the estimate, grey: " << m_inspection.pairs.size()
		   << " pairs";
	if (!m_inspection.parts.empty())
		legend << "; dark: " << m_inspection.parts.size() - dropped << " parts kept, orange: "
			   << dropped << " dropped";
	dc.DrawText(legend.str(), 5, bottom + 20);
	dc.DrawText(m_caption, 5, bottom + 38);
}
}  // namespace featloc
