#pragma once
#include <stdexcept>
#include <string>

namespace featloc
{
/** A configuration problem: a bad value, an unknown key or section, an
 * unknown class name. The message always names where the value came from
 * (file and line, or the command-line --set option), the section and the key.
 */
class ConfigError : public std::runtime_error
{
   public:
	explicit ConfigError(const std::string& message)
		: std::runtime_error(message)
	{
	}
};
}  // namespace featloc
