#pragma once
#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/config/CConfigFileMemory.h>

#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace YAML
{
class Node;
}

namespace featloc
{
/** An INI configuration (MRPT syntax) that remembers every key a component
 * asked for, so that keys nobody reads (typos, stale options) can be
 * reported as errors naming the section and key, as libpointmatcher and
 * Cartographer do.
 *
 * Values come from one file and from command-line overrides
 * ("Section:key=value", the --set option). Each value remembers its origin
 * (file and line, or the override) so that errors can point at it, and
 * relative paths are resolved against the ini file's folder for file values
 * and against the working directory for overrides.
 *
 * Sections and keys are case-insensitive, as in MRPT. */
class TrackedConfig : public mrpt::config::CConfigFileBase
{
   public:
	TrackedConfig() = default;

	/** Loads an ini file, or a YAML file (.yaml, .yml) of sections of keys.
	 * Throws ConfigError if it cannot be read. */
	void loadFile(const std::string& path);

	/** Loads YAML text: a map of sections, each a map of keys; a list of
	 * numbers becomes "[a b c]" and a list of lists "[x0 y0; x1 y1]". Errors
	 * name `originName` and the line. */
	void loadYaml(
		const std::string& yaml, const std::string& originName,
		const std::string& baseDir = ".");

	/** Loads ini text; `originName` names it in error messages. Relative paths
	 * in it resolve against `baseDir`. */
	void loadText(
		const std::string& text, const std::string& originName,
		const std::string& baseDir = ".");

	/** Applies one "Section:key=value" override. Throws ConfigError when the
	 * text has not that form. */
	void applyOverride(const std::string& spec);

	/** Where a key's value came from: "file.ini:12", "--set S:k=v", or "" if
	 * the key is absent. */
	std::string origin(const std::string& section, const std::string& key)
		const;

	/** Resolves a path-valued key: absolute paths stay, relative ones are
	 * taken relative to the folder of the file the value came from (or the
	 * working directory for --set). Empty stays empty. The key is
	 * remembered as a path (contentWithResolvedPaths). */
	std::string resolvePath(
		const std::string& section, const std::string& key,
		const std::string& value) const;

	/** Every (section, key) present in the configuration that no component
	 * asked for. */
	std::vector<std::pair<std::string, std::string>> unreadKeys() const;

	/** Counts every key of `section` as read: a section that belongs to
	 * another component (featloc-live's sensor sections in a replay). */
	void acceptSection(const std::string& section);

	/** Throws ConfigError listing every unread key, its origin, and the keys
	 * the section does accept (with a "did you mean" when one is close). */
	void requireAllKeysRead() const;

	/** Keys that some component asked for in a section, as spelled by the
	 * component. */
	std::set<std::string> queriedKeys(const std::string& section) const;

	/** Name of the file loaded (or the origin name of the text). */
	const std::string& sourceName() const { return m_sourceName; }

	/** The whole configuration as ini text. */
	std::string content() const { return m_values.getContent(); }
	/** The same, with every key resolved as a path so far (resolvePath)
	 * written as an absolute path, its comment kept: a copy that runs from
	 * any folder (a run's config_used.ini). */
	std::string contentWithResolvedPaths() const;

	void getAllSections(std::vector<std::string>& sections) const override;
	void getAllKeys(const std::string& section, std::vector<std::string>& keys)
		const override;
	void clear() override;

   protected:
	void writeString(
		const std::string& section, const std::string& name,
		const std::string& str) override;
	std::string readString(
		const std::string& section, const std::string& name,
		const std::string& defaultStr,
		bool failIfNotFound = false) const override;

   private:
	/** loadYaml's sections and keys (yaml-cpp throws on a non-scalar key or
	 * item; loadYaml turns that into a ConfigError). */
	void readYamlSections(
		const YAML::Node& root, const std::string& originName, const std::string& baseDir);

	struct Origin
	{
		std::string description;  //!< "file.ini:12" or "--set S:k=v"
		std::string baseDir;  //!< for relative paths
	};
	using Key = std::pair<std::string, std::string>;	 // lower case
	static Key makeKey(const std::string& section, const std::string& key);

	mrpt::config::CConfigFileMemory m_values;
	std::string m_sourceName;
	std::map<Key, Origin> m_origins;
	mutable std::set<Key> m_pathKeys;  //!< keys resolvePath was asked about
	struct QueriedSection
	{
		std::string name;  //!< as spelled by the component
		std::map<std::string, std::string> keys;  //!< lower case -> spelling
	};
	mutable std::map<std::string, QueriedSection> m_queried;  //!< by lower name
};

}  // namespace featloc
