#pragma once
#include <mrpt/serialization/CSerializable.h>

#include <cstddef>

namespace featloc
{
/** One object of a rawlog file: a CSensoryFrame or CActionCollection
 * (format #1, "actions/sensory frames") or a single CObservation (format
 * #2, "observations only"). `index` is its 0-based position in the file,
 * the number error messages and RawLogViewer use. */
struct RawlogEntry
{
	size_t index = 0;
	mrpt::serialization::CSerializable::Ptr object;
};
}  // namespace featloc
