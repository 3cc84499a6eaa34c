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
 * estimated robot pose of each processed scan as an
 * mrpt::obs::CObservationRobotPose (sensor label from [Output] pose_label,
 * the scan's timestamp, pose with covariance) placed right after the scan:
 * inside the scan's sensory frame (format #1), or as the next entry
 * (format #2). RawLogViewer and rawlog-edit open it.
 *
 * An entry is written once the poses of all its scans are known (format #2
 * scans can wait for the next odometry reading), so the file grows during
 * the run; finish() writes what remains, without poses for scans that were
 * never processed. Compressed with gzip. */
class EstimatedRawlogWriter : public RunOutput
{
   public:
	EstimatedRawlogWriter(std::string path, std::string poseLabel);
	~EstimatedRawlogWriter() override;

	void onEntry(
		const RawlogEntry& entry,
		const std::vector<ScanStepAssembler::SelectedScan>& selected) override;
	void onStep(const StepRecord& record) override;
	void finish(const RunStats& stats) override;
	std::string path() const override { return m_path; }

	size_t entriesWritten() const { return m_written; }

   private:
	struct Pending
	{
		RawlogEntry entry;
		std::vector<ScanStepAssembler::SelectedScan> scans;
	};
	void flush(bool all);
	void write(const Pending& p);

	std::string m_path;
	std::string m_poseLabel;
	struct Impl;
	std::unique_ptr<Impl> m_impl;
	std::deque<Pending> m_pending;
	std::map<size_t, mrpt::poses::CPosePDFGaussian> m_poses;  // by scanIndex
	size_t m_written = 0;
};
}  // namespace featloc
