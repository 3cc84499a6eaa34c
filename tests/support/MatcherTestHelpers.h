#pragma once
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPosePDFGaussian.h>
#include <mrpt/random/RandomGenerators.h>

#include <array>
#include <string>

#include "featloc/matchers/ScanMatcher.h"

namespace featloc::test
{
/** A registered matcher with its defaults and `overrides` on top (ini
 * lines "key=value", one per line). */
ScanMatcher::Ptr configuredMatcher(const std::string& cls, const std::string& overrides = "");

/** The scan with Gaussian range noise of `sigma` [m] on its valid beams. */
mrpt::obs::CObservation2DRangeScan::Ptr withRangeNoise(
	mrpt::obs::CObservation2DRangeScan::Ptr scan, mrpt::random::CRandomGenerator& rng,
	double sigma);

/** The two scans of a pair featloc-bench matched, saved in tests/data
 * (`file` is the name there): the first two 2-D scans, as observations or
 * in sensory frames. */
void readScanPair(const std::string& file, mrpt::obs::CObservation2DRangeScan& reference,
	mrpt::obs::CObservation2DRangeScan& current);

/** A match's initial guess as a run's matches.txt prints it: guess_x
 * guess_y guess_yaw, and g_xx g_xy g_xyaw g_yy g_yyaw g_yawyaw. */
mrpt::poses::CPosePDFGaussian guessFromMatchTable(
	const mrpt::poses::CPose2D& mean, const std::array<double, 6>& g);
}  // namespace featloc::test
