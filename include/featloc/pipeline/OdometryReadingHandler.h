#pragma once
#include "featloc/pipeline/ObservationHandler.h"

namespace featloc
{
/** CObservationOdometry (format #2) -> an absolute odometry reading; the
 * StepAssembler interpolates them at each step's time. A reading without
 * a valid timestamp, or with a non-finite pose, is an InputError. */
class OdometryReadingHandler : public ObservationHandler
{
   public:
	const mrpt::rtti::TRuntimeClassId* observationClass() const override;
	bool handle(
		const mrpt::obs::CObservation::Ptr& obs, size_t entryIndex, const std::string& where,
		ObservationContribution& out) override;
};
}  // namespace featloc
