#pragma once
#include <memory>
#include <string>

#include "featloc/output/RunOutput.h"

namespace mrpt::maps
{
class CSimpleMap;
}

namespace featloc
{
/** map.simplemap: the run's map in MRPT's CSimpleMap format, so that one
 * run's output is the next run's `[Localization] map` (and what
 * pf-localization, icp-slam's tools and RawLogViewer's map builder read).
 * One pair per keyframe scan: the scan as the log gave it, at the robot's
 * pose estimated then, with its covariance (CPose3DPDFGaussian). Written
 * (gzip-compressed, as MRPT writes it) when the run ends. */
class SimpleMapWriter : public RunOutput
{
   public:
	explicit SimpleMapWriter(std::string path);
	~SimpleMapWriter() override;
	void onStep(const StepRecord& record) override;
	void finish(const RunStats& stats) override;
	std::string path() const override { return m_path; }

   private:
	std::string m_path;
	std::unique_ptr<mrpt::maps::CSimpleMap> m_map;
};
}  // namespace featloc
