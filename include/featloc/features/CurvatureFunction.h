#pragma once
#include <mrpt/config/CLoadableOptions.h>

#include <string>
#include <vector>

#include "featloc/scan/ScanPoints.h"
#include "featloc/scan/ScanSegment.h"

namespace featloc
{
/** Nunez et al.'s adaptive curvature function of one scan segment
 * (CF-IDC, CF-SMA1, eqs. 4-6).
 *
 * For each point i of the segment:
 *  1. k_i, the largest window to the right of i that has no
 *     discontinuity: sum_{j=i}^{i+k_i-1} d(j, j+1) - d(i, i+k_i) < U_k
 *     (eq. 4: path length minus chord length; the difference never
 *     decreases with k, so the window ends where the outline starts to
 *     bend away by U_k);
 *  2. theta_i, the direction of the chord from i to i+k_i (eq. 5: the
 *     sums of the x and y steps telescope to that chord; atan2(dy, dx)
 *     here where the paper writes arctan(dx / dy), which flips every angle
 *     alike and changes no similarity);
 *  3. eta_i = theta_{i+1} - theta_i (eq. 6).
 *
 * Resampling (section III.B.1 asks for one power-of-two length for the
 * FFT; the paper does not say how): the unwrapped theta is sampled at
 * equally spaced arc-length positions and differenced, so eta keeps its
 * meaning (turn per sample) and does not depend on how densely the laser
 * sampled the outline from where it stood. Two spacings:
 *  - normalized (the paper): every segment to `length` samples, whatever
 *    its length;
 *  - metric (featloc): one sample per `step` metres of outline, the
 *    matcher padding all functions to one power-of-two length. A wall seen
 *    a little further along from the next pose keeps its shape sample for
 *    sample, instead of being stretched onto the same 64 samples. */
class CurvatureFunction
{
   public:
	struct Parameters : public mrpt::config::CLoadableOptions
	{
		double U_k = 1.0;  //!< [m] U_k of eq. (4)
		std::string sampling = "metric";  //!< metric | normalized
		unsigned int length = 64;  //!< normalized: samples, a power of two
		double step = 0.1;	//!< metric: [m] of outline per sample

		void loadFromConfigFile(
			const mrpt::config::CConfigFileBase& c,
			const std::string& s) override;
		void saveToConfigFile(
			mrpt::config::CConfigFileBase& c,
			const std::string& s) const override;
	};

	CurvatureFunction() = default;
	explicit CurvatureFunction(const Parameters& p) : params(p) {}

	/** eta of `segment` in `out`: params.length values (normalized), or
	 * one per `step` metres of outline (metric: `step` is params.step, or
	 * larger when the caller must bound the length). A segment of fewer
	 * than two points, or of zero length, gives zeros (no turn). */
	void compute(
		const ScanPoints& points, const ScanSegment& segment, std::vector<double>& out,
		double step = 0);

	/** Length of the outline through the segment's points [m]. */
	static double arcLength(const ScanPoints& points, const ScanSegment& segment);

	/** theta_i of eq. (5) for each point of the last computed segment
	 * (unwrapped), for inspection and tests. */
	const std::vector<double>& lastDirections() const { return m_theta; }
	/** k_i of eq. (4) for each point of the last computed segment. */
	const std::vector<unsigned int>& lastWindows() const { return m_window; }

	Parameters params;

   private:
	std::vector<double> m_arc, m_theta;	 // reused buffers
	std::vector<unsigned int> m_window;
};
}  // namespace featloc
