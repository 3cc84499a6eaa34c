#pragma once
#include <string>
#include <vector>

namespace featloc
{
/** A line chart saved as PNG (OpenCV): categories along x (labelled
 * ticks, evenly spaced), a value axis in [yMin, yMax], one polyline with
 * markers per series, and a legend. featloc-bench's basin curve (success
 * rate against initial error) is one. */
class CurvePlot
{
   public:
	struct Series
	{
		std::string label;
		std::vector<double> values;	 //!< one per x label
	};
	std::string title, xLabel, yLabel;
	std::vector<std::string> xTicks;
	double yMin = 0, yMax = 100;
	std::vector<Series> series;
	/** Series 2k and 2k+1 are one thing with and without an option: one
	 * colour, the second dashed with square markers. */
	bool pairedSeries = false;

	/** Throws std::runtime_error if the file cannot be written. */
	void save(const std::string& pngPath, int width = 900, int height = 600) const;
};
}  // namespace featloc
