#pragma once
#include "featloc/output/TextRowWriter.h"

namespace featloc
{
/** matches.txt: one row per scan match (the format is MatchTableFile's):
 * what the matcher started from, what it found, whether the estimator used
 * it and why not. featloc-viewer's match view reads it. */
class MatchTableWriter : public TextRowWriter
{
   public:
	explicit MatchTableWriter(std::string path);
	void onStep(const StepRecord& record) override;
};
}  // namespace featloc
