#include "featloc/scan/LaserScanSelector.h"

#include <cmath>
#include <sstream>

#include "featloc/core/InputError.h"

namespace featloc
{
LaserScanSelector::LaserScanSelector(
	std::string rawlogName, std::string label, std::string invalidPolicy)
	: m_rawlogName(std::move(rawlogName)),
	  m_label(std::move(label)),
	  m_labelFixed(!m_label.empty()),
	  m_invalidate(invalidPolicy == "invalidate")
{
}

mrpt::obs::CObservation2DRangeScan::Ptr LaserScanSelector::select(
	const mrpt::obs::CObservation::Ptr& obs, size_t entryIndex)
{
	auto scan = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(obs);
	if (!scan) return nullptr;
	m_scansPerLabel[scan->sensorLabel]++;
	const std::string where =
		"rawlog '" + m_rawlogName + "': entry #" + std::to_string(entryIndex);

	if (!m_labelFixed)
	{
		if (m_scansPerLabel.size() == 1 && m_scansPerLabel.begin()->second == 1)
		{
			m_label = scan->sensorLabel;
			m_firstEntryOfLabel = entryIndex;
		}
		else if (scan->sensorLabel != m_label)
		{
			throw InputError(
				where + " holds a 2-D scan from sensor '" + scan->sensorLabel +
				"', but entry #" + std::to_string(m_firstEntryOfLabel) +
				" held one from '" + m_label +
				"': the log has several lasers; choose one with [Input] "
				"laser_label");
		}
	}
	else if (scan->sensorLabel != m_label)
		return nullptr;

	if (scan->timestamp == INVALID_TIMESTAMP)
		throw InputError(
			where + ": 2-D scan '" + scan->sensorLabel +
			"' has no valid timestamp");

	// Bearings come from aperture and beam count: a bad value would place
	// every point wrongly without any other sign.
	if (!(std::isfinite(scan->aperture) && scan->aperture > 0 &&
		  scan->aperture <= 2 * M_PI + 1e-6) ||
		!(std::isfinite(scan->maxRange) && scan->maxRange > 0))
	{
		std::ostringstream msg;
		msg << where << ": 2-D scan '" << scan->sensorLabel
			<< "' has an impossible geometry (aperture " << scan->aperture
			<< " rad, maxRange " << scan->maxRange << " m)";
		throw InputError(msg.str());
	}

	mrpt::obs::CObservation2DRangeScan::Ptr out = scan;
	const size_t n = scan->getScanSize();
	for (size_t i = 0; i < n; i++)
	{
		if (!scan->getScanRangeValidity(i)) continue;
		const float r = scan->getScanRange(i);
		if (std::isfinite(r) && r >= 0) continue;
		if (!m_invalidate)
		{
			std::ostringstream msg;
			msg << where << ": 2-D scan '" << scan->sensorLabel << "' beam "
				<< i << " of " << n << " is marked valid but its range is "
				<< r
				<< " (set [Input] invalid_range_policy = invalidate to drop "
				   "such beams)";
			throw InputError(msg.str());
		}
		if (out == scan)
			out = std::make_shared<mrpt::obs::CObservation2DRangeScan>(*scan);
		out->setScanRangeValidity(i, false);
		m_invalidatedBeams++;
	}
	return out;
}
}  // namespace featloc
