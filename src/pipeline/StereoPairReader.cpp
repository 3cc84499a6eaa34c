#include "featloc/pipeline/StereoPairReader.h"

#include <mrpt/obs/CSensoryFrame.h>

#include "featloc/io/DecodedStereoPair.h"

namespace featloc
{
StereoPairReader::StereoPairReader(const std::string& rawlogPath)
	: m_source(rawlogPath), m_handler(m_source.imagesDirectory())
{
}

bool StereoPairReader::next(Pair& pair)
{
	RawlogEntry e;
	while (m_pending.empty() && m_source.next(e))
	{
		std::vector<mrpt::obs::CObservation::Ptr> observations;
		if (auto sf = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(e.object))
			observations.assign(sf->begin(), sf->end());
		else if (auto o = std::dynamic_pointer_cast<mrpt::obs::CObservation>(e.object))
			observations.push_back(o);
		for (const auto& o : observations)
		{
			if (!o->GetRuntimeClass()->derivedFrom(m_handler.observationClass())) continue;
			ObservationContribution c;
			const std::string where = "'" + m_source.name() + "' entry " + std::to_string(e.index);
			m_handler.handle(o, e.index, where, c);
			m_pending.push_back({e.index, c.stereo, c.stereoImages});
		}
	}
	if (m_pending.empty()) return false;
	pair = m_pending.front();
	m_pending.pop_front();
	return true;
}
}  // namespace featloc
