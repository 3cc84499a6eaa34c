#pragma once
#include <mrpt/obs/CObservationStereoImages.h>

#include <deque>
#include <memory>
#include <string>

#include "featloc/io/RawlogFileSource.h"
#include "featloc/pipeline/StereoImagesHandler.h"

namespace featloc
{
/** The stereo pairs of a rawlog, one by one, checked and decoded as
 * featloc-run checks them (StereoImagesHandler: calibration, images found
 * beside the rawlog as RawLogViewer finds them, sizes); other
 * observations are skipped. For tools that look at pairs alone (the
 * real-pair benchmark and its tests). */
class StereoPairReader
{
   public:
	struct Pair
	{
		size_t entry = 0;  //!< rawlog entry index
		std::shared_ptr<mrpt::obs::CObservationStereoImages> observation;
		std::shared_ptr<const DecodedStereoPair> images;
	};

	explicit StereoPairReader(const std::string& rawlogPath);

	/** The next pair; false at the end. Throws InputError naming the
	 * entry on a broken pair. */
	bool next(Pair& pair);

   private:
	RawlogFileSource m_source;
	StereoImagesHandler m_handler;
	std::deque<Pair> m_pending;	 //!< pairs of a sensory frame not yet returned
};
}  // namespace featloc
