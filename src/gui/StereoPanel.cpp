#include "featloc/gui/StereoPanel.h"

#include <mrpt/config/CConfigFile.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/obs/CObservationStereoImages.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPose3D.h>
#include <wx/dcbuffer.h>
#include <wx/image.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <sstream>

#include "featloc/core/ExceptionText.h"
#include "featloc/io/DecodedStereoPair.h"
#include "featloc/output/StereoPairPicture.h"
#include "featloc/stereo/StableVerticalLandmarks.h"
#include "featloc/stereo/StereoVerticalLines.h"

namespace featloc
{
namespace
{
wxBitmap toBitmap(const cv::Mat& bgr)
{
	if (bgr.empty()) return wxBitmap();
	cv::Mat rgb;
	cv::cvtColor(bgr, rgb, bgr.channels() == 1 ? cv::COLOR_GRAY2RGB : cv::COLOR_BGR2RGB);
	wxImage img(rgb.cols, rgb.rows);
	std::copy(rgb.data, rgb.data + rgb.total() * 3, img.GetData());
	return wxBitmap(img);
}

// The segment-stage options of the run's StableVerticalLandmarks (its
// [StereoLandmarks.StableVerticalLandmarks] section, without the map file,
// which the segment stage does not need).
StereoVerticalLines::Options segmentStageOptions(const std::string& configPath)
{
	StableVerticalLandmarks extractor;
	if (!configPath.empty())
	{
		mrpt::config::CConfigFile cfg(configPath);
		const std::string section = "StereoLandmarks.StableVerticalLandmarks";
		mrpt::config::CConfigFileMemory copy;
		std::vector<std::string> keys;
		cfg.getAllKeys(section, keys);
		for (const auto& k : keys)
			if (k != "map") copy.write(section, k, cfg.read_string(section, k, ""));
		extractor.loadParams(copy, section);
	}
	return extractor.segmentStageOptions();
}
}  // namespace

StereoPanel::StereoPanel(wxWindow* parent) : wxPanel(parent)
{
	SetBackgroundStyle(wxBG_STYLE_PAINT);
	Bind(wxEVT_PAINT, &StereoPanel::onPaint, this);
}

void StereoPanel::setResults(const RunResults& results)
{
	m_results = &results;
	m_options.reset();
	m_optionsError.clear();
	if (!results.stereo.empty())
		try
		{
			m_options = segmentStageOptions(results.configPath);
		}
		catch (const std::exception& e)
		{
			m_optionsError = exceptionText(e);
		}
	setStep(0);
}

void StereoPanel::setStep(size_t i)
{
	m_runPicture = m_pairPicture = wxBitmap();
	m_text.clear();
	const RunResults::StereoFrame* f = m_results ? m_results->stereoAt(i) : nullptr;
	if (!f)
	{
		m_text = "no stereo pair at this step";
		Refresh(false);
		return;
	}
	std::ostringstream text;
	if (!f->debugPicture.empty())
		m_runPicture = toBitmap(cv::imread(f->debugPicture, cv::IMREAD_COLOR));
	else
		text << "the run wrote no picture of this step ([Output] stereo_debug_every); ";
	if (!m_options)
		text << "segment stage not run: " << m_optionsError;
	else
		try
		{
			const StereoVerticalLines lines(*m_options);
			const auto& s = m_results->steps[i];
			const mrpt::poses::CPose3D camera =
				mrpt::poses::CPose3D(mrpt::poses::CPose2D(s.pose)) +
				mrpt::poses::CPose3D(f->observation->cameraPose);
			const auto r = lines.extract(f->images->left, f->images->right,
				f->observation->getStereoCameraParams(), camera, "step " + std::to_string(i));
			size_t supported = 0;
			for (const auto& why : r.matchRejection) supported += why.empty() ? 1 : 0;
			m_pairPicture = toBitmap(StereoPairPicture::draw(f->images->left, f->images->right, r));
			text << "segment stage: " << r.left.size() << " left and " << r.right.size()
				 << " right segments, " << r.matches.size() << " DP matches, " << supported
				 << " supported by the SAD disparity, " << r.lines.size() << " vertical lines";
		}
		catch (const std::exception& e)
		{
			text << "segment stage not run: " << exceptionText(e);
		}
	m_text = text.str();
	Refresh(false);
}

void StereoPanel::onPaint(wxPaintEvent&)
{
	wxAutoBufferedPaintDC dc(this);
	dc.SetBackground(*wxWHITE_BRUSH);
	dc.Clear();
	const wxSize size = GetClientSize();
	dc.DrawText(m_text, 5, 3);
	// The two pictures stacked, each scaled to the width and half the
	// height left.
	int y = 22;
	const int each = (size.y - y) / 2;
	for (const wxBitmap* b : {&m_runPicture, &m_pairPicture})
	{
		if (!b->IsOk() || each <= 10) continue;
		const double scale = std::min(size.x / double(b->GetWidth()), each / double(b->GetHeight()));
		const wxImage img = b->ConvertToImage().Scale(
			std::max(1, int(b->GetWidth() * scale)), std::max(1, int(b->GetHeight() * scale)),
			wxIMAGE_QUALITY_BILINEAR);
		dc.DrawBitmap(wxBitmap(img), 0, y);
		y += img.GetHeight() + 4;
	}
}
}  // namespace featloc
