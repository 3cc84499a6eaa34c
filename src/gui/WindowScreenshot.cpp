#include "featloc/gui/WindowScreenshot.h"

#include <wx/bitmap.h>
#include <wx/dcclient.h>
#include <wx/dcmemory.h>
#include <wx/image.h>
#include <wx/window.h>

#include <stdexcept>

namespace featloc
{
void WindowScreenshot::save(wxWindow& window, const std::string& pngPath)
{
	window.Update();
	// Copies from the X server, where the child windows and the GL
	// canvases have been drawn.
	wxClientDC screen(&window);
	const wxSize size = window.GetClientSize();
	wxBitmap bitmap(size.x, size.y);
	{
		wxMemoryDC memory(bitmap);
		memory.Blit(0, 0, size.x, size.y, &screen, 0, 0);
	}
	if (!wxImage::FindHandler(wxBITMAP_TYPE_PNG)) wxImage::AddHandler(new wxPNGHandler);
	if (!bitmap.SaveFile(pngPath, wxBITMAP_TYPE_PNG))
		throw std::runtime_error("cannot write the screenshot '" + pngPath + "'");
}
}  // namespace featloc
