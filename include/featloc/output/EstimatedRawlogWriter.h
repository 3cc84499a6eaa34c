#pragma once
#include <deque>
#include <map>
#include <memory>
#include <string>

#include <mrpt/poses/CPosePDFGaussian.h>

#include "featloc/output/RunOutput.h"

namespace featloc
{
/** estimated.rawlog: every input entry, in the input's own format, plus the
 * estimated robot pose of each processed step as an
 * mrpt::obs::CObservationRobotPose (sensor label from [Output] pose_label,
 * the step's timestamp, pose with covariance) placed right after the step's
 * primary observation (its scan, else its first landmark observation):
 * inside that observation's sensory frame (format #1), or as the next entry
 * (format #2). RawLogViewer and rawlog-edit open it.
 *
 * An entry is written once the poses of all the steps it fed are known
 * (format #2 steps can wait for the next odometry reading), so the file
 * grows during the run; finish() writes what remains, without poses for
 * steps that were never processed. Compressed with gzip. */
class EstimatedRawlogWriter : public RunOutput
{
   public:
	EstimatedRawlogWriter(std::string path, std::string poseLabel);
	~EstimatedRawlogWriter() override;

	void onEntry(
		const RawlogEntry& entry, const std::vector<StepSource>& used) override;
	void onStep(const StepRecord& record) override;
	void finish(const RunStats& stats) override;
	std::string path() const override { return m_path; }

	size_t entriesWritten() const { return m_written; }

   private:
	struct Pending
	{
		RawlogEntry entry;
		std::vector<StepSource> used;
	};
	void flush(bool all);
	void write(const Pending& p);

	std::string m_path;
	std::string m_poseLabel;
	struct Impl;
	std::unique_ptr<Impl> m_impl;
	std::deque<Pending> m_pending;
	struct StepPose
	{
		mrpt::poses::CPosePDFGaussian pose;
		const mrpt::obs::CObservation* source = nullptr;
		mrpt::Clock::time_point time{};
	};
	std::map<size_t, StepPose> m_poses;	 // by step index
	size_t m_written = 0;
};
}  // namespace featloc
