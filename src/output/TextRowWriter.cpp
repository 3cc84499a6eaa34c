#include "featloc/output/TextRowWriter.h"

#include <stdexcept>

namespace featloc
{
TextRowWriter::TextRowWriter(std::string path, const std::string& header)
	: m_path(std::move(path)), m_out(m_path)
{
	if (!m_out) throw std::runtime_error("cannot write '" + m_path + "'");
	m_out << "# " << header << "\n";
}

void TextRowWriter::writeRow(const char* row)
{
	m_out << row << '\n' << std::flush;
}

void TextRowWriter::finish(const RunStats&) { m_out.close(); }

std::string TextRowWriter::token(std::string text)
{
	if (text.empty()) return "-";
	for (char& c : text)
		if (c == ' ') c = '_';
	return text;
}
}  // namespace featloc
