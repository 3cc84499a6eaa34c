#include "featloc/config/TrackedConfig.h"

#include "featloc/core/ExceptionText.h"

#include <mrpt/system/filesystem.h>
#include <mrpt/system/string_utils.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "featloc/core/ConfigError.h"

namespace featloc
{
namespace
{
std::string lower(const std::string& s)
{
	std::string r = s;
	std::transform(r.begin(), r.end(), r.begin(), [](unsigned char c) {
		return static_cast<char>(std::tolower(c));
	});
	return r;
}

size_t editDistance(const std::string& a, const std::string& b)
{
	std::vector<size_t> prev(b.size() + 1), cur(b.size() + 1);
	for (size_t j = 0; j <= b.size(); j++) prev[j] = j;
	for (size_t i = 1; i <= a.size(); i++)
	{
		cur[0] = i;
		for (size_t j = 1; j <= b.size(); j++)
		{
			const size_t subst = prev[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
			cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, subst});
		}
		std::swap(prev, cur);
	}
	return prev[b.size()];
}

std::string closest(const std::string& word, const std::set<std::string>& pool)
{
	std::string best;
	size_t bestDist = std::max<size_t>(2, word.size() / 3) + 1;
	for (const auto& cand : pool)
	{
		const size_t d = editDistance(lower(word), lower(cand));
		if (d < bestDist)
		{
			bestDist = d;
			best = cand;
		}
	}
	return best;
}

/** Walks ini text as MRPT's parser reads it: "[section]", "key = value //
 * comment", whole-line comments starting with '#' or ';' (a line starting
 * with "//" and holding an '=' is a key to MRPT's parser). Calls
 * onKey(section, key, lineNo, line) for every key line (lineNo from 1),
 * which may rewrite `line`, and returns the text with those rewrites. */
template <typename OnKey>
std::string forEachKeyLine(const std::string& text, OnKey&& onKey)
{
	std::istringstream in(text);
	std::ostringstream out;
	std::string line, section;
	for (int lineNo = 1; std::getline(in, line); lineNo++)
	{
		const std::string t = mrpt::system::trim(line);
		if (!t.empty() && t[0] == '[')
		{
			const auto close = t.find(']');
			section = t.substr(1, close == std::string::npos ? std::string::npos : close - 1);
		}
		else if (!t.empty() && t[0] != '#' && t[0] != ';')
		{
			const auto eq = t.find('=');
			if (eq != std::string::npos) onKey(section, t.substr(0, eq), lineNo, line);
		}
		out << line << "\n";
	}
	return out.str();
}

std::string joined(const std::set<std::string>& items)
{
	std::string out;
	for (const auto& i : items) out += (out.empty() ? "" : ", ") + i;
	return out;
}
}  // namespace

TrackedConfig::Key TrackedConfig::makeKey(
	const std::string& section, const std::string& key)
{
	return {lower(mrpt::system::trim(section)), lower(mrpt::system::trim(key))};
}

void TrackedConfig::loadFile(const std::string& path)
{
	if (mrpt::system::directoryExists(path))
		throw ConfigError(
			"config file '" + path + "' is a directory, not an ini file (see config.ini)");
	if (!mrpt::system::fileExists(path))
		throw ConfigError("config file '" + path + "' does not exist");
	std::ifstream f(path);
	if (!f) throw ConfigError("config file '" + path + "' cannot be read");
	std::stringstream ss;
	ss << f.rdbuf();
	std::string dir = mrpt::system::extractFileDirectory(path);
	if (dir.empty()) dir = ".";
	const std::string ext = lower(mrpt::system::extractFileExtension(path));
	if (ext == "yaml" || ext == "yml")
		loadYaml(ss.str(), path, dir);
	else
		loadText(ss.str(), path, dir);
}

void TrackedConfig::loadYaml(
	const std::string& yaml, const std::string& originName,
	const std::string& baseDir)
{
	// A map of sections, each a map of keys. Values: scalars as they are;
	// a sequence of numbers as "[a b c]", a sequence of sequences as
	// "[x0 y0; x1 y1]" (the ini's matrix notation). yaml-cpp, not MRPT's
	// setContentFromYAML, which rejects sections with a single key in 2.5.8.
	auto where = [&](const YAML::Node& n) {
		return originName + ":" + std::to_string(n.Mark().line + 1);
	};
	YAML::Node root;
	try
	{
		root = YAML::Load(yaml);
	}
	catch (const YAML::Exception& e)
	{
		throw ConfigError(originName + ": not valid YAML: " + e.what());
	}
	m_values.clear();
	m_origins.clear();
	m_sourceName = originName;
	if (root.IsNull()) return;
	if (!root.IsMap())
		throw ConfigError(
			where(root) + ": expected a map of sections (Section: {key: value})");
	try
	{
		readYamlSections(root, originName, baseDir);
	}
	catch (const YAML::Exception& e)
	{
		// A key or an item that is not a scalar where one is needed
		// (yaml-cpp's "bad conversion"): found by fuzz/fuzz_world_file.
		throw ConfigError(originName + ":" + std::to_string(e.mark.line + 1) + ": " + e.msg +
			" (keys and list items must be scalars)");
	}
}

void TrackedConfig::readYamlSections(
	const YAML::Node& root, const std::string& originName, const std::string& baseDir)
{
	auto where = [&](const YAML::Node& n) {
		return originName + ":" + std::to_string(n.Mark().line + 1);
	};
	auto scalarList = [&](const YAML::Node& seq, const std::string& at) {
		std::string out;
		for (const auto& item : seq)
		{
			if (!item.IsScalar())
				throw ConfigError(at + ": nested lists go at most two deep ([[x, y], ...])");
			out += (out.empty() ? "" : " ") + item.as<std::string>();
		}
		return out;
	};
	for (const auto& sec : root)
	{
		const std::string section = sec.first.as<std::string>();
		if (!sec.second.IsMap())
			throw ConfigError(
				where(sec.second) + ": section '" + section + "' must be a map of keys");
		for (const auto& kv : sec.second)
		{
			const std::string key = kv.first.as<std::string>();
			const YAML::Node& v = kv.second;
			const std::string at = where(v) + ": [" + section + "] " + key;
			std::string text;
			if (v.IsScalar())
				text = v.as<std::string>();
			else if (v.IsNull())
				text = "";
			else if (v.IsSequence())
			{
				bool rows = v.size() > 0 && v[0].IsSequence();
				text = "[";
				for (size_t i = 0; i < v.size(); i++)
				{
					if (rows != v[i].IsSequence())
						throw ConfigError(at + ": mixes numbers and lists");
					text += rows ? (i ? "; " : "") + scalarList(v[i], at)
								 : (i ? " " : "") + v[i].as<std::string>();
				}
				text += "]";
			}
			else
				throw ConfigError(at + ": a value must be a scalar or a list");
			m_values.write(section, key, text);
			m_origins[makeKey(section, key)] = {where(kv.first), baseDir};
		}
	}
}

void TrackedConfig::loadText(
	const std::string& text, const std::string& originName,
	const std::string& baseDir)
{
	try
	{
		m_values.setContent(text);
	}
	catch (const std::exception& e)
	{
		// MRPT's preprocessor ($env{}, $eval{}, @define) throws a bare
		// runtime_error ("Line 51: Expected closing `}`"): say which file.
		throw ConfigError(originName + ": " + exceptionText(e));
	}
	m_sourceName = originName;
	m_origins.clear();

	// Remember the line of every key, for error messages.
	forEachKeyLine(text, [&](const std::string& section, const std::string& key, int lineNo,
							 std::string&) {
		m_origins[makeKey(section, key)] = {originName + ":" + std::to_string(lineNo), baseDir};
	});
}

void TrackedConfig::applyOverride(const std::string& spec)
{
	const auto colon = spec.find(':');
	const auto eq = spec.find('=', colon == std::string::npos ? 0 : colon);
	if (colon == std::string::npos || eq == std::string::npos || colon == 0 ||
		eq == colon + 1)
		throw ConfigError(
			"--set '" + spec +
			"': expected the form SECTION:KEY=VALUE, for example "
			"--set ScanMatcher:class=featloc::IcpMatcher");
	const std::string section = mrpt::system::trim(spec.substr(0, colon));
	const std::string key =
		mrpt::system::trim(spec.substr(colon + 1, eq - colon - 1));
	const std::string value = mrpt::system::trim(spec.substr(eq + 1));
	m_values.write(section, key, value);
	m_origins[makeKey(section, key)] = {"--set " + spec, "."};
}

std::string TrackedConfig::origin(
	const std::string& section, const std::string& key) const
{
	const auto it = m_origins.find(makeKey(section, key));
	return it == m_origins.end() ? std::string() : it->second.description;
}

std::string TrackedConfig::resolvePath(
	const std::string& section, const std::string& key,
	const std::string& value) const
{
	m_pathKeys.insert(makeKey(section, key));
	if (value.empty() || value[0] == '/') return value;
	const auto it = m_origins.find(makeKey(section, key));
	const std::string base =
		it == m_origins.end() ? std::string(".") : it->second.baseDir;
	if (base == "." || base.empty()) return value;
	return base + (base.back() == '/' ? "" : "/") + value;
}

std::string TrackedConfig::contentWithResolvedPaths() const
{
	// A line-by-line rewrite of the ini text, so that its layout and
	// comments stay: "key = value  // comment" of a path key whose value is
	// relative becomes "key = /absolute/value  // comment".
	return forEachKeyLine(content(), [&](const std::string& section, const std::string& key, int,
										 std::string& line) {
		if (!m_pathKeys.count(makeKey(section, key))) return;
		const size_t eq = line.find('=');
		const std::string rest = line.substr(eq + 1);
		const size_t comment = rest.find("//");
		const std::string value = mrpt::system::trim(rest.substr(0, comment));
		if (value.empty() || value[0] == '/') return;
		line = line.substr(0, eq + 1) + " " +
			std::filesystem::absolute(resolvePath(section, key, value)).lexically_normal().string() +
			(comment == std::string::npos ? "" : "  " + rest.substr(comment));
	});
}

std::vector<std::pair<std::string, std::string>> TrackedConfig::unreadKeys()
	const
{
	std::vector<std::pair<std::string, std::string>> out;
	std::vector<std::string> sections;
	m_values.getAllSections(sections);
	for (const auto& s : sections)
	{
		std::vector<std::string> keys;
		m_values.getAllKeys(s, keys);
		const auto q = m_queried.find(lower(s));
		for (const auto& k : keys)
			if (q == m_queried.end() || !q->second.keys.count(lower(k)))
				out.emplace_back(s, k);
	}
	return out;
}

std::set<std::string> TrackedConfig::queriedKeys(
	const std::string& section) const
{
	std::set<std::string> out;
	const auto it = m_queried.find(lower(section));
	if (it != m_queried.end())
		for (const auto& [low, spelled] : it->second.keys) out.insert(spelled);
	return out;
}

void TrackedConfig::requireAllKeysRead() const
{
	const auto unread = unreadKeys();
	if (unread.empty()) return;

	std::set<std::string> knownSections;
	for (const auto& [low, q] : m_queried) knownSections.insert(q.name);

	std::ostringstream msg;
	msg << "configuration has " << unread.size()
		<< " key(s) that no component reads:";
	for (const auto& [section, key] : unread)
	{
		const std::string where = origin(section, key);
		msg << "\n  " << (where.empty() ? m_sourceName : where) << ": ["
			<< section << "] " << key;
		const auto known = queriedKeys(section);
		if (known.empty())
		{
			msg << ": unknown section [" << section << "]";
			const std::string guess = closest(section, knownSections);
			if (!guess.empty()) msg << " (did you mean [" << guess << "]?)";
		}
		else
		{
			msg << ": unknown key";
			const std::string guess = closest(key, known);
			if (!guess.empty()) msg << " (did you mean '" << guess << "'?)";
			msg << "; keys of this section: " << joined(known);
		}
	}
	throw ConfigError(msg.str());
}

void TrackedConfig::getAllSections(std::vector<std::string>& sections) const
{
	m_values.getAllSections(sections);
}

void TrackedConfig::getAllKeys(
	const std::string& section, std::vector<std::string>& keys) const
{
	m_values.getAllKeys(section, keys);
}

void TrackedConfig::clear()
{
	m_values.clear();
	m_origins.clear();
	m_queried.clear();
}

void TrackedConfig::writeString(
	const std::string& section, const std::string& name, const std::string& str)
{
	m_values.write(section, name, str);
}

void TrackedConfig::acceptSection(const std::string& section)
{
	std::vector<std::string> keys;
	getAllKeys(section, keys);
	for (const auto& k : keys) readString(section, k, "");
}

std::string TrackedConfig::readString(
	const std::string& section, const std::string& name,
	const std::string& defaultStr, bool failIfNotFound) const
{
	const Key k = makeKey(section, name);
	auto& q = m_queried[k.first];
	if (q.name.empty()) q.name = mrpt::system::trim(section);
	q.keys.emplace(k.second, mrpt::system::trim(name));
	return m_values.read_string(section, name, defaultStr, failIfNotFound);
}

}  // namespace featloc
