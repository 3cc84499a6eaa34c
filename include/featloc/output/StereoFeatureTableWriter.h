#pragma once
#include <fstream>
#include <string>

#include "featloc/output/RunOutput.h"

namespace featloc
{
/** stereo_features.txt: every feature the stereo landmark extractor
 * modelled, pair by pair, with the columns of Moon, Miura & Shirai's
 * Table 1 (plane, index from the boundary, x, y, l, sigma_x, sigma_y,
 * length similarity, selected, reason) and the EKF landmark it updated or
 * started. Written as the run goes (a killed run keeps the rows so far). */
class StereoFeatureTableWriter : public RunOutput
{
   public:
	explicit StereoFeatureTableWriter(std::string path);
	void onStep(const StepRecord& record) override;
	void finish(const RunStats& stats) override;
	std::string path() const override { return m_path; }

   private:
	std::string m_path;
	std::ofstream m_out;
};
}  // namespace featloc
