#pragma once
#include "featloc/pipeline/ObservationHandler.h"
#include "featloc/scan/LaserScanSelector.h"

namespace featloc
{
/** CObservation2DRangeScan -> the scan of a step, for the scan matcher.
 * Which laser and which beams: LaserScanSelector ([Input] laser_label,
 * invalid_range_policy). */
class LaserScanHandler : public ObservationHandler
{
   public:
	explicit LaserScanHandler(LaserScanSelector selector) : m_selector(std::move(selector)) {}

	const mrpt::rtti::TRuntimeClassId* observationClass() const override;
	bool handle(
		const mrpt::obs::CObservation::Ptr& obs, size_t entryIndex, const std::string& where,
		ObservationContribution& out) override;

	const LaserScanSelector& selector() const { return m_selector; }

   private:
	LaserScanSelector m_selector;
};
}  // namespace featloc
