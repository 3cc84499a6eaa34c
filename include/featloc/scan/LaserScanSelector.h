#pragma once
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <cstddef>
#include <map>
#include <string>

namespace featloc
{
/** Picks the 2-D laser scans a run uses and checks them.
 *
 * - Label: with an empty `label`, the first 2-D scan's sensor label is
 *   taken, and a scan from a second label is an error (the log has several
 *   lasers: the user must choose one). With a label, other scans are
 *   ignored.
 * - Timestamp: a selected scan without a valid timestamp is an error.
 * - Ranges: a beam marked valid whose range is NaN, infinite or negative is
 *   an error naming entry and beam, or, with policy "invalidate", the scan
 *   is copied with that beam marked invalid (counted). */
class LaserScanSelector
{
   public:
	LaserScanSelector(
		std::string rawlogName, std::string label, std::string invalidPolicy);

	/** The scan to use (the observation itself, or a cleaned copy), or
	 * nullptr when `obs` is not a selected 2-D scan. */
	mrpt::obs::CObservation2DRangeScan::Ptr select(
		const mrpt::obs::CObservation::Ptr& obs, size_t entryIndex);

	size_t invalidatedBeams() const { return m_invalidatedBeams; }
	const std::string& label() const { return m_label; }
	/** Scans seen per sensor label (selected or not). */
	const std::map<std::string, size_t>& scansPerLabel() const
	{
		return m_scansPerLabel;
	}

   private:
	std::string m_rawlogName;
	std::string m_label;
	bool m_labelFixed;
	bool m_invalidate;
	size_t m_firstEntryOfLabel = 0;
	size_t m_invalidatedBeams = 0;
	std::map<std::string, size_t> m_scansPerLabel;
};
}  // namespace featloc
