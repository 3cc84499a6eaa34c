#pragma once
#include <stdexcept>
#include <string>

namespace featloc
{
/** A bad command line (missing argument, unknown option). */
class UsageError : public std::runtime_error
{
   public:
	explicit UsageError(const std::string& message)
		: std::runtime_error(message)
	{
	}
};
}  // namespace featloc
