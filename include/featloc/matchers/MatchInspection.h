#pragma once
#include <mrpt/math/TPoint2D.h>

#include <cstdint>
#include <string>
#include <vector>

namespace featloc
{
/** What a matcher used in its last match, for people looking at it
 * (featloc-viewer's match view): ScanMatcher::inspectLastMatch() fills it.
 * Reference items are in the reference scan's sensor frame, current items in
 * the current scan's sensor frame (the frames ScanMatcher::matchPoints works
 * in); the viewer places them with the scans' sensor poses and the
 * estimate. */
struct MatchInspection
{
	/** A reference point and the current point paired with it. */
	struct PointPair
	{
		mrpt::math::TPoint2D reference, current;
	};
	/** A run of scan points the matcher treated as one thing: a segment (IDC,
	 * CF-IDC), a line or a cluster (PCM), and what became of it. */
	struct Part
	{
		bool current = false;  //!< of the current scan (else the reference)
		bool kept = true;  //!< used by the match (else dropped)
		std::string kind;  //!< "segment", "line", "ellipse"
		std::vector<mrpt::math::TPoint2D> points;  //!< its points, in order
		std::vector<uint32_t> beams;  //!< each point's beam index in its scan
		std::string note;  //!< why kept or dropped, or how it was paired
	};

	/** How `pairs` were obtained, for the legend (e.g. "PCM feature pairs",
	 * "nearest neighbours at the estimate within 0.3 m"). */
	std::string pairsDescription;
	std::vector<PointPair> pairs;
	std::vector<Part> parts;
};
}  // namespace featloc
