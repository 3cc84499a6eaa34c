#pragma once
#include <string>

#include "featloc/output/TextRowWriter.h"

namespace featloc
{
/** stereo_features.txt: every feature the stereo landmark extractor
 * modelled, pair by pair, with the columns of Moon, Miura & Shirai's
 * Table 1 (plane, index from the boundary, x, y, l, sigma_x, sigma_y,
 * length similarity, selected, reason) and the EKF landmark it updated or
 * started. Written as the run goes (a killed run keeps the rows so far). */
class StereoFeatureTableWriter : public TextRowWriter
{
   public:
	explicit StereoFeatureTableWriter(std::string path);
	void onStep(const StepRecord& record) override;
};
}  // namespace featloc
