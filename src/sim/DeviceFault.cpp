#include "featloc/sim/DeviceFault.h"

#include <cmath>
#include <stdexcept>

namespace featloc
{
namespace
{
double seconds(const std::string& text, const std::string& spec)
{
	size_t used = 0;
	double v = NAN;
	try
	{
		v = std::stod(text, &used);
	}
	catch (const std::exception&)
	{
	}
	if (used != text.size() || !std::isfinite(v) || v < 0)
		throw std::invalid_argument("'" + spec + "': '" + text +
			"' is not a time in seconds >= 0 (forms: outage@T:D, stall@T:D, garbage@T)");
	return v;
}
}  // namespace

DeviceFault DeviceFault::parse(const std::string& spec)
{
	const auto at = spec.find('@');
	if (at == std::string::npos)
		throw std::invalid_argument(
			"'" + spec + "': expected outage@T:D, stall@T:D or garbage@T (seconds from the log's start)");
	const std::string kind = spec.substr(0, at), rest = spec.substr(at + 1);
	DeviceFault f;
	if (kind == "outage" || kind == "stall")
	{
		const auto colon = rest.find(':');
		if (colon == std::string::npos)
			throw std::invalid_argument(
				"'" + spec + "': " + kind + " needs its length: " + kind + "@T:D");
		f.kind = kind == "outage" ? Kind::Outage : Kind::Stall;
		f.at = seconds(rest.substr(0, colon), spec);
		f.duration = seconds(rest.substr(colon + 1), spec);
	}
	else if (kind == "garbage")
	{
		f.kind = Kind::Garbage;
		f.at = seconds(rest, spec);
	}
	else
		throw std::invalid_argument(
			"'" + spec + "': unknown fault '" + kind + "' (known: outage@T:D, stall@T:D, garbage@T)");
	return f;
}

std::string DeviceFault::describe() const
{
	char text[96];
	if (kind == Kind::Outage)
		std::snprintf(text, sizeof(text), "outage at %.1f s for %.1f s", at, duration);
	else if (kind == Kind::Stall)
		std::snprintf(text, sizeof(text), "stall (link up, silent) at %.1f s for %.1f s", at,
			duration);
	else
		std::snprintf(text, sizeof(text), "malformed scan at %.1f s", at);
	return text;
}
}  // namespace featloc
