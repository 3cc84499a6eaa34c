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

void EstimatedRawlogWriter::onEntry(const RawlogEntry& entry, const std::vector<StepSource>& used)
{
	m_pending.push_back({entry, used});
	flush(false);
}

void EstimatedRawlogWriter::onStep(const StepRecord& r)
{
	m_poses[r.step.index] = {r.pose, r.step.source, r.step.time};
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
		for (const auto& s : p.used) complete = complete && m_poses.count(s.stepIndex);
		if (!complete && !all) break;
		write(p);
		const std::vector<StepSource> done = p.used;
		m_pending.pop_front();
		// A step can feed several entries (format #2 observations that
		// share a time): keep its pose until the last of them is written.
		for (const auto& s : done)
		{
			bool needed = false;
			for (const auto& q : m_pending)
				for (const auto& u : q.used) needed = needed || u.stepIndex == s.stepIndex;
			if (!needed) m_poses.erase(s.stepIndex);
		}
	}
}

void EstimatedRawlogWriter::write(const Pending& p)
{
	using namespace mrpt::obs;
	// The pose observation of the step whose primary observation is
	// `source`, if its pose is known.
	auto poseOf = [&](const CObservation* source) -> CObservation::Ptr {
		for (const auto& s : p.used)
		{
			if (s.observation != source) continue;
			const auto it = m_poses.find(s.stepIndex);
			if (it == m_poses.end() || it->second.source != source) return nullptr;
			auto obs = std::make_shared<CObservationRobotPose>();
			obs->sensorLabel = m_poseLabel;
			obs->timestamp = it->second.time;
			obs->pose = mrpt::poses::CPose3DPDFGaussian(it->second.pose);
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
