#pragma once
#include <mrpt/math/TPose2D.h>
#include <mrpt/obs/obs_frwds.h>
#include <wx/panel.h>

#include <memory>
#include <string>

#include "featloc/matchers/MatchInspection.h"

namespace featloc
{
/** One match drawn in the reference scan's robot frame (wxDC): the
 * reference scan, the current scan placed by the match's estimate, the
 * pairs the matcher used, and its lines, clusters or segments (kept: a
 * thin dark line, dropped: thick orange; MatchPanel lists the reasons). */
class ScanPairPanel : public wxPanel
{
   public:
	ScanPairPanel(wxWindow* parent, std::string title);
	/** `estimate`: robot-frame motion from the reference to the current
	 * scan; `inspection` in the scans' sensor frames (MatchInspection). */
	void setMatch(std::shared_ptr<mrpt::obs::CObservation2DRangeScan> reference,
		std::shared_ptr<mrpt::obs::CObservation2DRangeScan> current,
		const mrpt::math::TPose2D& estimate, MatchInspection inspection,
		const std::string& caption);
	void clear(const std::string& message);

	static constexpr unsigned char kReference[3] = {0, 160, 160};
	static constexpr unsigned char kCurrent[3] = {230, 30, 30};
	static constexpr unsigned char kDropped[3] = {255, 150, 0};

   private:
	void onPaint(wxPaintEvent&);

	std::string m_title, m_caption, m_message;
	std::shared_ptr<mrpt::obs::CObservation2DRangeScan> m_reference, m_current;
	mrpt::math::TPose2D m_estimate;
	MatchInspection m_inspection;
};
}  // namespace featloc
