#pragma once
/** Strict reading and commented writing of configuration values.
 *
 * MRPT's read_double()/read_int() parse with atof/atoi: "abc" silently
 * becomes 0 and "12abc" becomes 12. featloc's option structs read through
 * these helpers instead, which reject anything that is not entirely a value
 * of the expected type and name the file, line, section and key. A key that
 * is absent keeps the value the variable already has (the in-class default).
 */
#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/typemeta/TEnumType.h>

#include <string>
#include <vector>

namespace featloc::config
{
/** Raw text of a key (trimmed, "//" comments removed); false when the key is
 * absent. */
bool readRaw(
	const mrpt::config::CConfigFileBase& c, const std::string& section,
	const std::string& key, std::string& text);

/** "file.ini:12: [Section] key = value" for error messages. */
std::string where(
	const mrpt::config::CConfigFileBase& c, const std::string& section,
	const std::string& key);

/** Throws ConfigError "<where>: <problem>". */
[[noreturn]] void fail(
	const mrpt::config::CConfigFileBase& c, const std::string& section,
	const std::string& key, const std::string& problem);

/** Throws ConfigError naming the key unless `ok`. */
void require(
	bool ok, const mrpt::config::CConfigFileBase& c, const std::string& section,
	const std::string& key, const std::string& requirement);

void read(
	const mrpt::config::CConfigFileBase& c, const std::string& section,
	const std::string& key, double& value);
void read(
	const mrpt::config::CConfigFileBase& c, const std::string& section,
	const std::string& key, float& value);
void read(
	const mrpt::config::CConfigFileBase& c, const std::string& section,
	const std::string& key, int& value);
void read(
	const mrpt::config::CConfigFileBase& c, const std::string& section,
	const std::string& key, unsigned int& value);
void read(
	const mrpt::config::CConfigFileBase& c, const std::string& section,
	const std::string& key, bool& value);
void read(
	const mrpt::config::CConfigFileBase& c, const std::string& section,
	const std::string& key, std::string& value);
/** A list of numbers written "[a b c]" or "a, b, c". */
void read(
	const mrpt::config::CConfigFileBase& c, const std::string& section,
	const std::string& key, std::vector<double>& value);

/** A list of rows written "[x0 y0; x1 y1; ...]" (MATLAB style; commas
 * also separate numbers). Every row must have one of `allowedColumns`
 * numbers. */
void readRows(
	const mrpt::config::CConfigFileBase& c, const std::string& section,
	const std::string& key, std::vector<std::vector<double>>& rows,
	const std::vector<size_t>& allowedColumns);

/** Reads a value given in degrees in the file into radians. The key name
 * should end in "_DEG". */
void readDegrees(
	const mrpt::config::CConfigFileBase& c, const std::string& section,
	const std::string& key, double& radians);

/** Reads one of a fixed set of words. */
void readChoice(
	const mrpt::config::CConfigFileBase& c, const std::string& section,
	const std::string& key, std::string& value,
	const std::vector<std::string>& allowed);

/** Reads an MRPT enum (with mrpt::typemeta::TEnumType) by its symbolic
 * name; a bad name lists the valid ones. */
template <typename Enum>
void readEnum(
	const mrpt::config::CConfigFileBase& c, const std::string& section,
	const std::string& key, Enum& value)
{
	std::string text;
	if (!readRaw(c, section, key, text)) return;
	try
	{
		value = mrpt::typemeta::TEnumType<Enum>::name2value(text);
	}
	catch (const std::exception&)
	{
		std::string names;
		for (const auto& kv : mrpt::typemeta::TEnumType<Enum>::getBimap())
			names += (names.empty() ? "" : ", ") + kv.second;
		fail(c, section, key, "'" + text + "' is not one of: " + names);
	}
}

/** Writes "key = value  // comment" (MRPT style). */
void write(
	mrpt::config::CConfigFileBase& c, const std::string& section,
	const std::string& key, const std::string& value,
	const std::string& comment);
void write(
	mrpt::config::CConfigFileBase& c, const std::string& section,
	const std::string& key, double value, const std::string& comment);
void write(
	mrpt::config::CConfigFileBase& c, const std::string& section,
	const std::string& key, int value, const std::string& comment);
void write(
	mrpt::config::CConfigFileBase& c, const std::string& section,
	const std::string& key, unsigned int value, const std::string& comment);
void write(
	mrpt::config::CConfigFileBase& c, const std::string& section,
	const std::string& key, bool value, const std::string& comment);
void write(
	mrpt::config::CConfigFileBase& c, const std::string& section,
	const std::string& key, const std::vector<double>& value,
	const std::string& comment);
void writeRows(
	mrpt::config::CConfigFileBase& c, const std::string& section,
	const std::string& key, const std::vector<std::vector<double>>& rows,
	const std::string& comment);
/** Writes radians as degrees. */
void writeDegrees(
	mrpt::config::CConfigFileBase& c, const std::string& section,
	const std::string& key, double radians, const std::string& comment);

template <typename Enum>
void writeEnum(
	mrpt::config::CConfigFileBase& c, const std::string& section,
	const std::string& key, Enum value, const std::string& comment)
{
	write(
		c, section, key, mrpt::typemeta::TEnumType<Enum>::value2name(value),
		comment);
}

/** Formats a double in the shortest form that reads back within 1e-12
 * (relative), so saved files show 0.2, not 0.20000000000000001. */
std::string formatNumber(double v);

}  // namespace featloc::config
