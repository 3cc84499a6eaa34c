#pragma once
#include <stdexcept>
#include <string>

namespace featloc
{
/** A problem with input data (rawlog, trajectory or relations file): missing,
 * truncated, corrupt or semantically invalid. The message names the file and
 * the entry (rawlog entry index, or line number for text files). */
class InputError : public std::runtime_error
{
   public:
	explicit InputError(const std::string& message)
		: std::runtime_error(message)
	{
	}
};
}  // namespace featloc
