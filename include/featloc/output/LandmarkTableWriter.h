#pragma once
#include <string>
#include <vector>

#include "featloc/ekf/EstimatedLandmark.h"
#include "featloc/output/RunOutput.h"

namespace featloc
{
/** landmarks.txt (estimator = ekf): the filter's point landmarks at the
 * end of the run, one row each: id x y c_xx c_xy c_yy observations (id -1:
 * the sensor gave none). Written in finish(), also after an error. */
class LandmarkTableWriter : public RunOutput
{
   public:
	explicit LandmarkTableWriter(std::string path) : m_path(std::move(path)) {}
	void onStep(const StepRecord& record) override;
	void finish(const RunStats& stats) override;
	std::string path() const override { return m_path; }

   private:
	/** The table into `file` (a temporary renamed to m_path). */
	void writeTable(const std::string& file) const;

	std::string m_path;
	std::vector<EstimatedLandmark> m_landmarks;
};
}  // namespace featloc
