#include "featloc/matchers/ScanMatcher.h"

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>

#include <chrono>

namespace featloc
{
IMPLEMENTS_VIRTUAL_MRPT_OBJECT(ScanMatcher, mrpt::rtti::CObject, featloc)

namespace
{
/** Fewer points than this cannot constrain a planar motion (3 dof). */
constexpr size_t kMinPointsPerScan = 3;

mrpt::poses::CPose2D planar(const mrpt::poses::CPose3D& p)
{
	return mrpt::poses::CPose2D(p);
}
}  // namespace

std::string ScanMatcher::className() const
{
	return GetRuntimeClass()->className;
}

MatchResult ScanMatcher::match(
	const mrpt::obs::CObservation2DRangeScan& reference,
	const mrpt::obs::CObservation2DRangeScan& current,
	const mrpt::poses::CPosePDFGaussian& initialGuess)
{
	const auto t0 = std::chrono::steady_clock::now();
	const mrpt::poses::CPose2D s1 = planar(reference.sensorPose);
	const mrpt::poses::CPose2D s2 = planar(current.sensorPose);

	// Robot motion X, sensor motion Y: X = S1 (+) Y (+) S2^-1, hence
	// Y = S1^-1 (+) X (+) S2. MRPT propagates the covariance through both
	// compositions with their Jacobians.
	mrpt::poses::CPosePDFGaussian sensorGuess = initialGuess;
	sensorGuess.changeCoordinatesReference(mrpt::poses::CPose2D() - s1);
	sensorGuess += s2;

	MatchResult r = match(
		ScanPoints::fromScan(reference), ScanPoints::fromScan(current),
		sensorGuess);

	r.estimate.changeCoordinatesReference(s1);
	r.estimate += mrpt::poses::CPose2D() - s2;
	r.timeSeconds =
		std::chrono::duration<double>(std::chrono::steady_clock::now() - t0)
			.count();
	return r;
}

MatchResult ScanMatcher::match(
	const ScanPoints& reference, const ScanPoints& current,
	const mrpt::poses::CPosePDFGaussian& initialGuess)
{
	const auto t0 = std::chrono::steady_clock::now();
	MatchResult r;
	r.estimate = initialGuess;
	r.referencePoints = reference.size();
	r.currentPoints = current.size();
	if (reference.size() < kMinPointsPerScan ||
		current.size() < kMinPointsPerScan)
	{
		r.success = false;
		r.failureReason = "too few valid points (reference " +
			std::to_string(reference.size()) + ", current " +
			std::to_string(current.size()) + "; need at least " +
			std::to_string(kMinPointsPerScan) + ")";
	}
	else
	{
		matchPoints(reference, current, initialGuess, r);
	}
	r.timeSeconds =
		std::chrono::duration<double>(std::chrono::steady_clock::now() - t0)
			.count();
	return r;
}

}  // namespace featloc
