#include "featloc/pipeline/OdometryReadingHandler.h"

#include <mrpt/obs/CObservationOdometry.h>

#include <cmath>

#include "featloc/core/InputError.h"

namespace featloc
{
const mrpt::rtti::TRuntimeClassId* OdometryReadingHandler::observationClass() const
{
	return CLASS_ID(mrpt::obs::CObservationOdometry);
}

bool OdometryReadingHandler::handle(
	const mrpt::obs::CObservation::Ptr& o, size_t, const std::string& where,
	ObservationContribution& out)
{
	const auto& odo = dynamic_cast<const mrpt::obs::CObservationOdometry&>(*o);
	if (odo.timestamp == INVALID_TIMESTAMP)
		throw InputError(
			where + ": odometry observation '" + odo.sensorLabel + "' has no valid timestamp");
	const auto& p = odo.odometry;
	if (!(std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.phi())))
		throw InputError(
			where + ": odometry observation '" + odo.sensorLabel + "' has a non-finite pose");
	out.odometryReading = p;
	return true;
}
}  // namespace featloc
