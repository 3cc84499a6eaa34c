#include "featloc/config/ConfigValues.h"

#include <mrpt/core/bits_math.h>
#include <mrpt/system/string_utils.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>

#include "featloc/config/TrackedConfig.h"
#include "featloc/core/ConfigError.h"

namespace featloc::config
{
namespace
{
std::string lower(std::string s)
{
	for (auto& ch : s) ch = static_cast<char>(std::tolower(ch));
	return s;
}

/** Parses the whole of `text` as a finite double; `out` is only written on
 * success. */
bool parseDouble(const std::string& text, double& out)
{
	if (text.empty()) return false;
	errno = 0;
	char* end = nullptr;
	const double v = std::strtod(text.c_str(), &end);
	if (errno != 0 || end != text.c_str() + text.size() || !std::isfinite(v))
		return false;
	out = v;
	return true;
}

bool parseLong(const std::string& text, long& out)
{
	if (text.empty()) return false;
	errno = 0;
	char* end = nullptr;
	const long v = std::strtol(text.c_str(), &end, 10);
	if (errno != 0 || end != text.c_str() + text.size()) return false;
	out = v;
	return true;
}

std::string quoted(const std::string& s) { return "'" + s + "'"; }
}  // namespace

bool readRaw(
	const mrpt::config::CConfigFileBase& c, const std::string& section,
	const std::string& key, std::string& text)
{
	// read_string() goes through readString(), which TrackedConfig records
	// as a query even when the key is absent: the key is known either way.
	const std::string value = c.read_string(section, key, "");
	if (!c.keyExists(section, key)) return false;
	text = mrpt::system::trim(value);
	// MRPT strips a "// comment" after a value, but not when the value is
	// empty ("key =   // comment"): that is an empty value, not the text.
	if (text.rfind("//", 0) == 0) text.clear();
	return true;
}

std::string where(
	const mrpt::config::CConfigFileBase& c, const std::string& section,
	const std::string& key)
{
	std::string origin;
	if (const auto* tc = dynamic_cast<const TrackedConfig*>(&c))
	{
		origin = tc->origin(section, key);
		if (origin.empty()) origin = tc->sourceName();
	}
	std::string out = origin.empty() ? "" : origin + ": ";
	out += "[" + section + "] " + key;
	if (c.keyExists(section, key))
		out += " = " + quoted(mrpt::system::trim(c.read_string(section, key, "")));
	return out;
}

void fail(
	const mrpt::config::CConfigFileBase& c, const std::string& section,
	const std::string& key, const std::string& problem)
{
	throw ConfigError(where(c, section, key) + ": " + problem);
}

void require(
	bool ok, const mrpt::config::CConfigFileBase& c, const std::string& section,
	const std::string& key, const std::string& requirement)
{
	if (!ok) fail(c, section, key, "must be " + requirement);
}

void read(
	const mrpt::config::CConfigFileBase& c, const std::string& section,
	const std::string& key, double& value)
{
	std::string text;
	if (!readRaw(c, section, key, text)) return;
	if (!parseDouble(text, value)) fail(c, section, key, "not a finite number");
}

void read(
	const mrpt::config::CConfigFileBase& c, const std::string& section,
	const std::string& key, float& value)
{
	double d = value;
	read(c, section, key, d);
	value = static_cast<float>(d);
}

void read(
	const mrpt::config::CConfigFileBase& c, const std::string& section,
	const std::string& key, int& value)
{
	std::string text;
	if (!readRaw(c, section, key, text)) return;
	long v = 0;
	if (!parseLong(text, v) || v < std::numeric_limits<int>::min() ||
		v > std::numeric_limits<int>::max())
		fail(c, section, key, "not an integer");
	value = static_cast<int>(v);
}

void read(
	const mrpt::config::CConfigFileBase& c, const std::string& section,
	const std::string& key, unsigned int& value)
{
	std::string text;
	if (!readRaw(c, section, key, text)) return;
	long v = 0;
	if (!parseLong(text, v) || v < 0 ||
		v > static_cast<long>(std::numeric_limits<unsigned int>::max()))
		fail(c, section, key, "not a non-negative integer");
	value = static_cast<unsigned int>(v);
}

void read(
	const mrpt::config::CConfigFileBase& c, const std::string& section,
	const std::string& key, bool& value)
{
	std::string text;
	if (!readRaw(c, section, key, text)) return;
	const std::string t = lower(text);
	if (t == "true" || t == "1" || t == "yes" || t == "on")
		value = true;
	else if (t == "false" || t == "0" || t == "no" || t == "off")
		value = false;
	else
		fail(c, section, key, "not a boolean (true/false, 1/0, yes/no, on/off)");
}

void read(
	const mrpt::config::CConfigFileBase& c, const std::string& section,
	const std::string& key, std::string& value)
{
	std::string text;
	if (readRaw(c, section, key, text)) value = text;
}

void read(
	const mrpt::config::CConfigFileBase& c, const std::string& section,
	const std::string& key, std::vector<double>& value)
{
	std::string text;
	if (!readRaw(c, section, key, text)) return;
	std::vector<std::string> tokens;
	mrpt::system::tokenize(text, "[], \t", tokens);
	std::vector<double> out;
	for (const auto& tok : tokens)
	{
		double d = 0;
		if (!parseDouble(tok, d))
			fail(c, section, key, "'" + tok + "' is not a finite number");
		out.push_back(d);
	}
	value = out;
}

void readRows(
	const mrpt::config::CConfigFileBase& c, const std::string& section,
	const std::string& key, std::vector<std::vector<double>>& rows,
	const std::vector<size_t>& allowedColumns)
{
	std::string text;
	if (!readRaw(c, section, key, text)) return;
	std::vector<std::string> rowTexts;
	mrpt::system::tokenize(text, "[];", rowTexts);
	std::vector<std::vector<double>> out;
	for (const auto& rowText : rowTexts)
	{
		std::vector<std::string> tokens;
		mrpt::system::tokenize(rowText, ", \t", tokens);
		if (tokens.empty()) continue;
		std::vector<double> row;
		for (const auto& tok : tokens)
		{
			double d = 0;
			if (!parseDouble(tok, d))
				fail(c, section, key,
					"'" + tok + "' in row " + std::to_string(out.size() + 1) +
						" is not a finite number");
			row.push_back(d);
		}
		bool ok = false;
		std::string allowed;
		for (size_t n : allowedColumns)
		{
			ok = ok || row.size() == n;
			allowed += (allowed.empty() ? "" : " or ") + std::to_string(n);
		}
		if (!ok)
			fail(c, section, key,
				"row " + std::to_string(out.size() + 1) + " has " +
					std::to_string(row.size()) + " numbers, expected " + allowed);
		out.push_back(row);
	}
	rows = out;
}

void readDegrees(
	const mrpt::config::CConfigFileBase& c, const std::string& section,
	const std::string& key, double& radians)
{
	double deg = mrpt::RAD2DEG(radians);
	read(c, section, key, deg);
	radians = mrpt::DEG2RAD(deg);
}

void readChoice(
	const mrpt::config::CConfigFileBase& c, const std::string& section,
	const std::string& key, std::string& value,
	const std::vector<std::string>& allowed)
{
	std::string text;
	if (!readRaw(c, section, key, text)) return;
	for (const auto& a : allowed)
		if (a == text)
		{
			value = text;
			return;
		}
	std::string list;
	for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
	fail(c, section, key, "must be one of: " + list);
}

std::string formatNumber(double v)
{
	// The shortest form that reads back within 1e-12 (relative): 0.2 rather
	// than 0.20000000000000001 for a value converted from radians.
	const double rounded = std::round(v);
	if (std::abs(v - rounded) <= 1e-12 * std::abs(v) && std::abs(v) < 1e15)
		return std::to_string(static_cast<long long>(rounded));
	for (int digits = 1; digits < std::numeric_limits<double>::max_digits10;
		 digits++)
	{
		std::ostringstream s;
		s.precision(digits);
		s << v;
		const double back = std::strtod(s.str().c_str(), nullptr);
		if (std::abs(back - v) <= 1e-12 * std::abs(v)) return s.str();
	}
	std::ostringstream s;
	s.precision(std::numeric_limits<double>::max_digits10);
	s << v;
	return s.str();
}

void write(
	mrpt::config::CConfigFileBase& c, const std::string& section,
	const std::string& key, const std::string& value,
	const std::string& comment)
{
	// Name padding 28, value padding 14: columns line up in generated files.
	c.write(section, key, value, 28, 14, comment);
}

void write(
	mrpt::config::CConfigFileBase& c, const std::string& section,
	const std::string& key, double value, const std::string& comment)
{
	write(c, section, key, formatNumber(value), comment);
}

void write(
	mrpt::config::CConfigFileBase& c, const std::string& section,
	const std::string& key, int value, const std::string& comment)
{
	write(c, section, key, std::to_string(value), comment);
}

void write(
	mrpt::config::CConfigFileBase& c, const std::string& section,
	const std::string& key, unsigned int value, const std::string& comment)
{
	write(c, section, key, std::to_string(value), comment);
}

void write(
	mrpt::config::CConfigFileBase& c, const std::string& section,
	const std::string& key, bool value, const std::string& comment)
{
	write(c, section, key, std::string(value ? "true" : "false"), comment);
}

void write(
	mrpt::config::CConfigFileBase& c, const std::string& section,
	const std::string& key, const std::vector<double>& value,
	const std::string& comment)
{
	std::string s = "[";
	for (size_t i = 0; i < value.size(); i++)
		s += (i ? " " : "") + formatNumber(value[i]);
	write(c, section, key, s + "]", comment);
}

void writeRows(
	mrpt::config::CConfigFileBase& c, const std::string& section,
	const std::string& key, const std::vector<std::vector<double>>& rows,
	const std::string& comment)
{
	std::string s = "[";
	for (size_t r = 0; r < rows.size(); r++)
	{
		if (r) s += "; ";
		for (size_t i = 0; i < rows[r].size(); i++)
			s += (i ? " " : "") + formatNumber(rows[r][i]);
	}
	write(c, section, key, s + "]", comment);
}

void writeDegrees(
	mrpt::config::CConfigFileBase& c, const std::string& section,
	const std::string& key, double radians, const std::string& comment)
{
	write(c, section, key, formatNumber(mrpt::RAD2DEG(radians)), comment);
}

}  // namespace featloc::config
