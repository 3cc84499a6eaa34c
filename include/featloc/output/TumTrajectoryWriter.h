#pragma once
#include "featloc/output/TextRowWriter.h"

namespace featloc
{
/** trajectory.tum: one row per processed scan, at the scan's timestamp, in
 * the TUM RGB-D benchmark format "t x y z qx qy qz qw" (z = 0, rotation
 * about Z only), 9 decimals for time and position. */
class TumTrajectoryWriter : public TextRowWriter
{
   public:
	explicit TumTrajectoryWriter(std::string path);
	void onStep(const StepRecord& record) override;
};
}  // namespace featloc
