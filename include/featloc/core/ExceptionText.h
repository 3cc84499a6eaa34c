#pragma once
#include <exception>
#include <string>

namespace featloc
{
/** One printable line for an exception caught around MRPT code: MRPT's
 * exceptions carry "Message:" lines (nested ones, innermost last; joined
 * with " <- ") and call stacks; when no message says anything, the
 * "Location:" line's text (MRPT's ini preprocessor puts "Line 45: Expected
 * closing `}`" there). Other exceptions: what(). Control and non-ASCII
 * bytes (read from damaged files) become '?', so that the text is valid
 * UTF-8 for summary.json. */
std::string exceptionText(const std::exception& e);
}  // namespace featloc
