#pragma once
#include <mrpt/serialization/CSerializable.h>

#include <fstream>
#include <string>

namespace featloc
{
/** A format-#2 rawlog written one object at a time and flushed after
 * each, so that whatever a live run received is on disk as soon as it is
 * recorded: a run killed at any moment leaves a rawlog readable up to its
 * last whole entry (RawLogViewer opens it; featloc-run replays it). */
class RawlogRecorder
{
   public:
	/** Creates (truncates) the file; throws std::runtime_error naming it
	 * when it cannot. */
	explicit RawlogRecorder(std::string path);

	/** Appends one object (an observation). Throws naming the file when
	 * the disk refuses it. */
	void record(const mrpt::serialization::CSerializable& object);

	const std::string& path() const { return m_path; }
	size_t entries() const { return m_entries; }
	size_t bytes() const { return m_bytes; }

   private:
	std::string m_path;
	std::ofstream m_file;
	size_t m_entries = 0, m_bytes = 0;
};
}  // namespace featloc
