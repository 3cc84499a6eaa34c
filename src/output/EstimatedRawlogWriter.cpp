#include "featloc/output/EstimatedRawlogWriter.h"

#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/obs/CObservationRobotPose.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose3DPDFGaussian.h>
#include <mrpt/serialization/CArchive.h>

#include <stdexcept>

namespace featloc
{
struct EstimatedRawlogWriter::Impl
{
	mrpt::io::CFileGZOutputStream file;
};

EstimatedRawlogWriter::EstimatedRawlogWriter(
	std::string path, std::string poseLabel)
	: m_path(std::move(path)),
	  m_poseLabel(std::move(poseLabel)),
	  m_impl(std::make_unique<Impl>())
{
	if (!m_impl->file.open(m_path))
		throw std::runtime_error("cannot write '" + m_path + "'");
}

EstimatedRawlogWriter::~EstimatedRawlogWriter() = default;

void EstimatedRawlogWriter::onEntry(
	const RawlogEntry& entry,
	const std::vector<ScanStepAssembler::SelectedScan>& selected)
{
	m_pending.push_back({entry, selected});
	flush(false);
}

void EstimatedRawlogWriter::onStep(const StepRecord& r)
{
	m_poses[r.step.scanIndex] = r.pose;
	flush(false);
}

void EstimatedRawlogWriter::finish(const RunStats&)
{
	flush(true);
	m_impl->file.close();
}

void EstimatedRawlogWriter::flush(bool all)
{
	while (!m_pending.empty())
	{
		const Pending& p = m_pending.front();
		bool complete = true;
		for (const auto& s : p.scans)
			complete = complete && m_poses.count(s.scanIndex);
		if (!complete && !all) break;
		write(p);
		for (const auto& s : p.scans) m_poses.erase(s.scanIndex);
		m_pending.pop_front();
	}
}

void EstimatedRawlogWriter::write(const Pending& p)
{
	using namespace mrpt::obs;
	// The pose observation of a scan, if its pose is known.
	auto poseOf = [&](const CObservation* source) -> CObservation::Ptr {
		for (const auto& s : p.scans)
		{
			if (s.source != source) continue;
			const auto it = m_poses.find(s.scanIndex);
			if (it == m_poses.end()) return nullptr;
			auto obs = std::make_shared<CObservationRobotPose>();
			obs->sensorLabel = m_poseLabel;
			obs->timestamp = source->timestamp;
			obs->pose = mrpt::poses::CPose3DPDFGaussian(it->second);
			return obs;
		}
		return nullptr;
	};

	auto arch = mrpt::serialization::archiveFrom(m_impl->file);
	if (auto sf = std::dynamic_pointer_cast<CSensoryFrame>(p.entry.object))
	{
		CSensoryFrame out;
		for (const auto& obs : *sf)
		{
			out.insert(obs);
			if (auto pose = poseOf(obs.get())) out.insert(pose);
		}
		arch << out;
	}
	else
	{
		arch << *p.entry.object;
		if (auto obs = std::dynamic_pointer_cast<CObservation>(p.entry.object))
			if (auto pose = poseOf(obs.get())) arch << *pose;
	}
	m_written++;
}
}  // namespace featloc
