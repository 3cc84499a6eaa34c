#pragma once
#include <string>

class wxWindow;

namespace featloc
{
/** Saves what a window shows on screen (its client area, children and
 * OpenGL canvases included) as a PNG. Throws std::runtime_error naming the
 * file when it cannot be written. */
class WindowScreenshot
{
   public:
	static void save(wxWindow& window, const std::string& pngPath);
};
}  // namespace featloc
