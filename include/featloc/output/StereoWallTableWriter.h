#pragma once
#include <string>

#include "featloc/output/TextRowWriter.h"

namespace featloc
{
/** stereo_walls.txt: every wall the stereo front end handed the EKF as an
 * observation of the pose (featloc's wall observations,
 * StereoWallObservation), pair by pair: its fitted line, sigmas, view
 * angle, coverage, Mahalanobis^2 against the EKF's belief and what the EKF
 * did with it. Written as the run goes. */
class StereoWallTableWriter : public TextRowWriter
{
   public:
	explicit StereoWallTableWriter(std::string path);
	void onStep(const StepRecord& record) override;
};
}  // namespace featloc
