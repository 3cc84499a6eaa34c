#pragma once
#include <mrpt/obs/obs_frwds.h>
#include <mrpt/poses/CPosePDFGaussian.h>

#include <memory>

#include "featloc/localization/LocalizationMap.h"
#include "featloc/localization/LocalizationOptions.h"
#include "featloc/matchers/MatchResult.h"
#include "featloc/matchers/ScanMatcher.h"

namespace featloc
{
/** Tracking in a known map: each scan matched against the map around the
 * predicted pose, by any registered matcher.
 *
 * The map gives the reference as a scan would: the current scan's beams
 * cast from the predicted pose into the map (LocalizationMap::virtualScan).
 * The matcher then estimates the current scan's pose in that virtual
 * scan's frame, a small correction delta, from the identity with the
 * prediction's covariance turned into the robot frame; the robot's pose in
 * the map is predicted (+) delta. Its covariance is the match's, turned
 * back into the map frame, times covariance_scale, plus min_sigma_* in
 * quadrature (the map's cells). The prediction is only where the virtual
 * scan is taken from: its own error is not in the measurement, so the
 * filter can fuse it as an independent absolute pose. */
class MapScanTracker
{
   public:
	MapScanTracker(
		std::shared_ptr<const LocalizationMap> map, ScanMatcher::Ptr matcher,
		LocalizationOptions options);

	struct Result
	{
		/** The matcher's result (its estimate is delta, robot frame). */
		MatchResult match;
		/** The robot's pose in the map with the covariance to fuse (valid
		 * when match.success). */
		mrpt::poses::CPosePDFGaussian pose;
		/** Beams of the virtual scan that hit the map. */
		size_t mapBeams = 0;
	};
	Result track(
		const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::poses::CPosePDFGaussian& predicted);

	const LocalizationMap& map() const { return *m_map; }
	const LocalizationOptions& options() const { return m_options; }
	const ScanMatcher& matcher() const { return *m_matcher; }

   private:
	std::shared_ptr<const LocalizationMap> m_map;
	ScanMatcher::Ptr m_matcher;
	LocalizationOptions m_options;
};
}  // namespace featloc
