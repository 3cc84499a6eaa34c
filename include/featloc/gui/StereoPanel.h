#pragma once
#include <wx/bitmap.h>
#include <wx/panel.h>

#include <optional>
#include <string>

#include "featloc/gui/RunResults.h"
#include "featloc/stereo/StereoVerticalLines.h"

namespace featloc
{
/** featloc-viewer's stereo page, for runs with stereo pairs: at the top the
 * run's own picture of the step (stereo_debug: detected, matched, on-plane
 * and selected vertical segments of Moon, Miura & Shirai, StereoDebugPicture),
 * below the left and right images with the segment stage run again with the
 * run's [StereoLandmarks] parameters (StereoPairPicture: detected segments,
 * DP matches the SAD disparity does or does not support). */
class StereoPanel : public wxPanel
{
   public:
	explicit StereoPanel(wxWindow* parent);
	void setResults(const RunResults& results);
	void setStep(size_t i);
	/** What the page says about the current step (for the tests). */
	const std::string& summaryText() const { return m_text; }

   private:
	void onPaint(wxPaintEvent&);

	const RunResults* m_results = nullptr;
	/** The segment stage's options, read once per results folder (or why
	 * they could not be). */
	std::optional<StereoVerticalLines::Options> m_options;
	std::string m_optionsError;
	wxBitmap m_runPicture, m_pairPicture;
	std::string m_text;
};
}  // namespace featloc
