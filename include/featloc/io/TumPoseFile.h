#pragma once
#include <mrpt/poses/CPose3D.h>

#include <string>
#include <vector>

namespace featloc
{
/** A TUM trajectory file of 3-D poses: rows `t x y z qx qy qz qw`, blank
 * lines and lines starting with '#' or '%' skipped. */
class TumPoseFile
{
   public:
	struct Row
	{
		double t = 0;  //!< [s]
		mrpt::poses::CPose3D pose;
		std::string text;  //!< the line as written
	};

	/** Throws InputError naming the file (and file:line for a row that is
	 * not a TUM row: it is not quietly left out of a ground truth). */
	static std::vector<Row> read(const std::string& path);

	/** The row nearest to time t within maxGap seconds, or nullptr. */
	static const Row* nearest(const std::vector<Row>& rows, double t, double maxGap);
};
}  // namespace featloc
