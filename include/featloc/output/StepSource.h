#pragma once
#include <mrpt/obs/obs_frwds.h>

#include <cstddef>

namespace featloc
{
/** An observation of a rawlog entry that went into a step: the outputs
 * that copy the input (estimated.rawlog) wait for that step's pose before
 * writing the entry. */
struct StepSource
{
	size_t stepIndex = 0;
	const mrpt::obs::CObservation* observation = nullptr;
};
}  // namespace featloc
