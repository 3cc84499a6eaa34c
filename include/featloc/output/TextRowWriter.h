#pragma once
#include <fstream>
#include <string>

#include "featloc/output/RunOutput.h"

namespace featloc
{
/** Base of the text outputs that write one row per processed scan: opens
 * the file with a '#' header line, flushes every row (a crash or an error
 * later in the run keeps the rows written), closes in finish(). */
class TextRowWriter : public RunOutput
{
   public:
	TextRowWriter(std::string path, const std::string& header);
	void finish(const RunStats& stats) override;
	std::string path() const override { return m_path; }

	/** `text` as one whitespace-separated column: spaces become '_', an
	 * empty text '-'. */
	static std::string token(std::string text);

   protected:
	/** Appends one line (without its newline) and flushes. */
	void writeRow(const char* row);

   private:
	std::string m_path;
	std::ofstream m_out;
};
}  // namespace featloc
