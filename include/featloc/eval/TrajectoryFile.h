#pragma once
#include <string>
#include <vector>

#include "featloc/eval/Trajectory.h"

namespace featloc
{
/** Reads trajectory and relation text files. Lines starting with '#' or
 * '%' (MRPT's comments) and blank lines are skipped; fields are separated
 * by spaces, tabs or commas.
 *
 * Formats (detected from the column count):
 * - TUM: "t x y z qx qy qz qw" (8 columns, unit quaternion; yaw is taken
 *   from the quaternion's rotation about Z);
 * - "t x y yaw" (4 columns, yaw in radians), as MRPT's ground-truth files;
 * - featloc's poses_cov.txt: "t x y yaw" + 6 covariance terms (10 columns);
 * - relations (Kummerle et al. 2009): "t1 t2 x y z roll pitch yaw"
 *   (8 columns, angles in radians; only x, y, yaw are used).
 * - MRPT robot path "x y z yaw pitch roll" (6 columns, as kf-slam's
 *   *_ground_truth_robot_path.txt): no times;
 * - KITTI "r11 r12 r13 tx r21 r22 r23 ty r31 r32 r33 tz" (12 columns, a
 *   3x4 pose matrix per row): no times. Z up: x = tx, y = ty, yaw from
 *   r11, r21; KITTI's camera convention (rotations about y, z forward, x
 *   right) is recognised and mapped to x = tz, y = -tx.
 * Formats without times get the row index as `t` and Trajectory::timed =
 * false: evaluation pairs their rows with the estimate's in order.
 * TUM and relations both have 8 columns: a file whose columns 5-8 are unit
 * quaternions on every row is TUM, otherwise relations. MRPT's ".GT.txt"
 * files are "t x y yaw".
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
		Relations,
		MrptRobotPath,
		Kitti
	};

	/** Detects the format of a file (never returns Auto). */
	static Format detect(const std::string& path);

	/** Reads a trajectory (TUM, t x y yaw, or poses_cov). Rows must be in
	 * increasing time. */
	static Trajectory read(
		const std::string& path, Format format = Format::Auto, Format* used = nullptr);

	/** Reads a relations file. */
	static std::vector<PoseRelation> readRelations(const std::string& path);

	/** Parses "auto", "tum", "txyyaw", "poses_cov", "relations". */
	static Format parseFormat(const std::string& name);
	static std::string formatName(Format f);
	/** A sentence for the console: which format was read ("TUM t x y z qx
	 * qy qz qw"). */
	static std::string formatDescription(Format f);
};
}  // namespace featloc
