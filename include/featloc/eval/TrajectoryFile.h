#pragma once
#include <string>
#include <vector>

#include "featloc/eval/Trajectory.h"

namespace featloc
{
/** Reads trajectory and relation text files. Lines starting with '#' and
 * blank lines are skipped; fields are separated by spaces, tabs or commas.
 *
 * Formats (detected from the column count):
 * - TUM: "t x y z qx qy qz qw" (8 columns, unit quaternion; yaw is taken
 *   from the quaternion's rotation about Z);
 * - "t x y yaw" (4 columns, yaw in radians), as MRPT's ground-truth files;
 * - featloc's poses_cov.txt: "t x y yaw" + 6 covariance terms (10 columns);
 * - relations (Kummerle et al. 2009): "t1 t2 x y z roll pitch yaw"
 *   (8 columns, angles in radians; only x, y, yaw are used).
 * TUM and relations both have 8 columns: a file whose columns 5-8 are unit
 * quaternions on every row is TUM, otherwise relations.
 *
 * Any malformed line is an InputError naming the file and line. */
class TrajectoryFile
{
   public:
	enum class Format
	{
		Auto,
		Tum,
		TimeXYYaw,
		PosesCov,
		Relations
	};

	/** Detects the format of a file (never returns Auto). */
	static Format detect(const std::string& path);

	/** Reads a trajectory (TUM, t x y yaw, or poses_cov). Rows must be in
	 * increasing time. */
	static Trajectory read(const std::string& path, Format format = Format::Auto);

	/** Reads a relations file. */
	static std::vector<PoseRelation> readRelations(const std::string& path);

	/** Parses "auto", "tum", "txyyaw", "poses_cov", "relations". */
	static Format parseFormat(const std::string& name);
	static std::string formatName(Format f);
};
}  // namespace featloc
