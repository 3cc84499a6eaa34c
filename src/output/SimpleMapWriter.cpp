#include "featloc/output/SimpleMapWriter.h"
#include "featloc/core/WholeFile.h"

#include <mrpt/maps/CSimpleMap.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose3DPDFGaussian.h>

#include <stdexcept>

namespace featloc
{
SimpleMapWriter::SimpleMapWriter(std::string path)
	: m_path(std::move(path)), m_map(std::make_unique<mrpt::maps::CSimpleMap>())
{
}

SimpleMapWriter::~SimpleMapWriter() = default;

void SimpleMapWriter::onStep(const StepRecord& r)
{
	if (!r.keyframe || !r.step.scan) return;
	auto sf = mrpt::obs::CSensoryFrame::Create();
	sf->insert(std::make_shared<mrpt::obs::CObservation2DRangeScan>(*r.step.scan));
	const auto pose = mrpt::poses::CPose3DPDFGaussian::Create(
		mrpt::poses::CPose3DPDFGaussian(mrpt::poses::CPosePDFGaussian(r.pose)));
	m_map->insert(pose, sf);
}

void SimpleMapWriter::finish(const RunStats&)
{
	writeWholeFile(m_path, [&](const std::string& file) {
		if (!m_map->saveToFile(file)) throw std::runtime_error("cannot write '" + m_path + "'");
	});
}
}  // namespace featloc
