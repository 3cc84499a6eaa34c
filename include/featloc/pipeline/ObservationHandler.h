#pragma once
#include <mrpt/obs/CObservation.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/obs_frwds.h>
#include <mrpt/poses/CPose2D.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "featloc/ekf/LandmarkObservation.h"

namespace featloc
{
/** What one observation gives the step assembler: something seen at the
 * observation's time (a scan, landmarks), or a motion reading. */
struct ObservationContribution
{
	/** A selected 2-D scan (a cleaned copy when beams were invalidated). */
	mrpt::obs::CObservation2DRangeScan::Ptr scan;
	/** Point landmarks in the robot frame. */
	std::vector<LandmarkObservation> landmarks;
	/** A checked stereo pair, and its images decoded grey. */
	std::shared_ptr<mrpt::obs::CObservationStereoImages> stereo;
	std::shared_ptr<const struct DecodedStereoPair> stereoImages;
	/** An absolute odometry reading (format #2 CObservationOdometry). */
	std::optional<mrpt::poses::CPose2D> odometryReading;
};

/** Decodes the observations of one MRPT class (and its subclasses) for the
 * pipeline: the StepAssembler looks each observation up by its RTTI class
 * and hands it to the handler that takes it. A class no handler takes is
 * counted and ignored.
 *
 * To add a sensor: derive a handler that turns its observation class into
 * scan, landmarks or motion, and register it with
 * StepAssembler::addHandler (stereo images give landmarks this way). */
class ObservationHandler
{
   public:
	using Ptr = std::unique_ptr<ObservationHandler>;
	virtual ~ObservationHandler() = default;

	/** The MRPT observation class this handler takes. */
	virtual const mrpt::rtti::TRuntimeClassId* observationClass() const = 0;

	/** Decodes and checks `obs`. Returns false when the observation is of
	 * the class but not used (a scan of another laser). Bad content is an
	 * InputError that begins with `where` (file and entry). */
	virtual bool handle(
		const mrpt::obs::CObservation::Ptr& obs, size_t entryIndex, const std::string& where,
		ObservationContribution& out) = 0;
};
}  // namespace featloc
