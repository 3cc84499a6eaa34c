#include "featloc/pipeline/BearingRangeHandler.h"

#include <mrpt/obs/CObservationBearingRange.h>

#include <Eigen/LU>
#include <cmath>

#include "featloc/core/InputError.h"

namespace featloc
{
const mrpt::rtti::TRuntimeClassId* BearingRangeHandler::observationClass() const
{
	return CLASS_ID(mrpt::obs::CObservationBearingRange);
}

bool BearingRangeHandler::handle(
	const mrpt::obs::CObservation::Ptr& o, size_t, const std::string& where,
	ObservationContribution& out)
{
	const auto& obs = dynamic_cast<const mrpt::obs::CObservationBearingRange&>(*o);
	if (obs.timestamp == INVALID_TIMESTAMP)
		throw InputError(
			where + ": range-bearing observation '" + obs.sensorLabel +
			"' has no valid timestamp");
	for (size_t i = 0; i < obs.sensedData.size(); i++)
	{
		const auto& m = obs.sensedData[i];
		const bool finite = std::isfinite(m.range) && std::isfinite(m.yaw) &&
			(!obs.validCovariances || m.covariance.array().isFinite().all());
		if (!finite || m.range < 0)
			throw InputError(
				where + ": range-bearing observation '" + obs.sensorLabel + "': landmark #" +
				std::to_string(i) + " has a negative or non-finite range, bearing or covariance");
	}
	out.landmarks = LandmarkObservation::fromBearingRange(obs);
	for (size_t i = 0; i < out.landmarks.size(); i++)
	{
		const auto& l = out.landmarks[i];
		// A zero or indefinite covariance would make the filter claim
		// certainty it has not got.
		if (!(l.covariance.determinant() > 0 && l.covariance(0, 0) > 0))
			throw InputError(
				where + ": range-bearing observation '" + obs.sensorLabel + "': landmark #" +
				std::to_string(i) +
				" has no positive-definite covariance (set sensor_std_range and "
				"sensor_std_yaw, or per-landmark covariances)");
	}
	m_observations++;
	return true;
}
}  // namespace featloc
