#pragma once
#include <string>

#include "featloc/pipeline/ObservationHandler.h"

namespace featloc
{
/** CObservationStereoImages -> a step holding the stereo pair (the stereo
 * landmark extractor reads it from there).
 *
 * Checks each pair before it is used, so that a broken log is an error
 * naming the entry and never a crash or a silent skip:
 *  - a valid timestamp;
 *  - both images present (hasImageRight), and a calibration: positive
 *    focal lengths and image size in leftCamera and rightCamera, and a
 *    right camera offset (rightCameraPose) that is finite and not zero;
 *  - images stored externally (MRPT's convention for large logs) exist
 *    and decode: a relative name is looked up in `imagesDirectory` (the
 *    rawlog's `<name>_Images` folder, as RawLogViewer does);
 *  - left and right have the same size, and the size the calibration says.
 * External names are then made absolute in the observation, so that
 * estimated.rawlog, written elsewhere, still finds the images. */
class StereoImagesHandler : public ObservationHandler
{
   public:
	explicit StereoImagesHandler(std::string imagesDirectory);

	const mrpt::rtti::TRuntimeClassId* observationClass() const override;
	bool handle(
		const mrpt::obs::CObservation::Ptr& obs, size_t entryIndex, const std::string& where,
		ObservationContribution& out) override;

	size_t pairs() const { return m_pairs; }

   private:
	std::string m_imagesDirectory;
	size_t m_pairs = 0;
};
}  // namespace featloc
