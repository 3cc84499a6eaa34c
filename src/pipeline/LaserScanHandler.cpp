#include "featloc/pipeline/LaserScanHandler.h"

namespace featloc
{
const mrpt::rtti::TRuntimeClassId* LaserScanHandler::observationClass() const
{
	return CLASS_ID(mrpt::obs::CObservation2DRangeScan);
}

bool LaserScanHandler::handle(
	const mrpt::obs::CObservation::Ptr& obs, size_t entryIndex, const std::string&,
	ObservationContribution& out)
{
	out.scan = m_selector.select(obs, entryIndex);
	return out.scan != nullptr;
}
}  // namespace featloc
