#pragma once
#include <fstream>
#include <string>

#include "featloc/output/RunOutput.h"

namespace featloc
{
/** trajectory.tum: one row per processed scan, at the scan's timestamp, in
 * the TUM RGB-D benchmark format "t x y z qx qy qz qw" (z = 0, rotation
 * about Z only), 9 decimals for time and position. Each row is flushed as
 * it is written. */
class TumTrajectoryWriter : public RunOutput
{
   public:
	explicit TumTrajectoryWriter(std::string path);
	void onStep(const StepRecord& record) override;
	void finish(const RunStats& stats) override;
	std::string path() const override { return m_path; }

   private:
	std::string m_path;
	std::ofstream m_out;
};
}  // namespace featloc
