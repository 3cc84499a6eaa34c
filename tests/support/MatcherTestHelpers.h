#pragma once
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/random/RandomGenerators.h>

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
 * (`file` is the name there). */
void readScanPair(const std::string& file, mrpt::obs::CObservation2DRangeScan& reference,
	mrpt::obs::CObservation2DRangeScan& current);
}  // namespace featloc::test
