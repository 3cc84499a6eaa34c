#include "featloc/core/ExceptionText.h"

#include <sstream>

namespace featloc
{
namespace
{
// The text after `label` on each line that has one, joined.
std::string linesAfter(const std::string& text, const std::string& label)
{
	std::istringstream in(text);
	std::string line, out;
	while (std::getline(in, line))
	{
		const auto pos = line.find(label);
		if (pos == std::string::npos) continue;
		std::string msg = line.substr(pos + label.size());
		const auto first = msg.find_first_not_of(" \t`");
		msg = first == std::string::npos ? "" : msg.substr(first);
		if (!msg.empty()) out += (out.empty() ? "" : " <- ") + msg;
	}
	return out;
}
}  // namespace

std::string exceptionText(const std::exception& e)
{
	const std::string text = e.what();
	std::string msg = linesAfter(text, "Message:");
	if (msg.empty()) msg = linesAfter(text, "Location:");
	if (msg.empty()) msg = text;
	for (char& c : msg)
	{
		const auto u = static_cast<unsigned char>(c);
		if ((u < 0x20 && c != '\n') || u >= 0x7f) c = '?';
	}
	return msg;
}
}  // namespace featloc
