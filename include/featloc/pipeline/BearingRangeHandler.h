#pragma once
#include "featloc/pipeline/ObservationHandler.h"

namespace featloc
{
/** CObservationBearingRange -> point landmarks of a step (range and
 * bearing; pitch ignored), in the robot frame with their covariances
 * (LandmarkObservation::fromBearingRange). A negative or non-finite range,
 * bearing or covariance, or a covariance that is not positive definite, is
 * an InputError naming the entry and landmark. */
class BearingRangeHandler : public ObservationHandler
{
   public:
	const mrpt::rtti::TRuntimeClassId* observationClass() const override;
	bool handle(
		const mrpt::obs::CObservation::Ptr& obs, size_t entryIndex, const std::string& where,
		ObservationContribution& out) override;

	size_t observations() const { return m_observations; }

   private:
	size_t m_observations = 0;
};
}  // namespace featloc
