#pragma once
#include <functional>
#include <string>

namespace featloc::test
{
/** The message of the `Error` that `f` throws, or "" when it throws nothing
 * (any other exception propagates and fails the test). */
template <typename Error>
std::string errorMessageOf(const std::function<void()>& f)
{
	try
	{
		f();
	}
	catch (const Error& e)
	{
		return e.what();
	}
	return "";
}
}  // namespace featloc::test
