#pragma once
#include <memory>
#include <string>
#include <vector>

namespace featloc
{
/** A metric top-view drawing saved as PNG (OpenCV): world coordinates in
 * metres mapped to a square image with a labelled grid, equal scale on both
 * axes, y up. Colours are RGB in [0, 255]. */
class PlotCanvas
{
   public:
	struct Rgb
	{
		int r, g, b;
	};
	struct Point
	{
		double x, y;
	};

	/** The canvas shows [minX, maxX] x [minY, maxY] (expanded to a square,
	 * with a margin). */
	PlotCanvas(double minX, double minY, double maxX, double maxY, int sizePx = 1000);
	~PlotCanvas();
	PlotCanvas(const PlotCanvas&) = delete;
	PlotCanvas& operator=(const PlotCanvas&) = delete;

	void line(const Point& a, const Point& b, Rgb colour, int thicknessPx = 1);
	void polyline(const std::vector<Point>& pts, Rgb colour, int thicknessPx = 2);
	void circle(const Point& c, double radiusMetres, Rgb colour, bool filled);
	/** A small marker of fixed pixel size. */
	void marker(const Point& c, Rgb colour, int radiusPx = 6);
	void dots(const std::vector<Point>& pts, Rgb colour);
	void title(const std::string& text);
	/** Legend entries are stacked in the top right corner. */
	void legend(const std::string& text, Rgb colour);

	/** Throws std::runtime_error if the file cannot be written. */
	void save(const std::string& pngPath) const;

   private:
	struct Impl;
	std::unique_ptr<Impl> m;
};
}  // namespace featloc
