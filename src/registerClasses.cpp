#include "featloc/registerClasses.h"

#include <mrpt/maps/registerAllClasses.h>
#include <mrpt/obs/registerAllClasses.h>
#include <mrpt/opengl/registerAllClasses.h>
#include <mrpt/poses/registerAllClasses.h>
#include <mrpt/rtti/CObject.h>

#include <mutex>

#include "featloc/estimators/EkfEstimator.h"
#include "featloc/estimators/MatcherChainEstimator.h"
#include "featloc/estimators/OdometryEstimator.h"
#include "featloc/estimators/PoseEstimator.h"
#include "featloc/live/TcpOdometrySensor.h"
#include "featloc/matchers/CfIdcMatcher.h"
#include "featloc/matchers/IcpMatcher.h"
#include "featloc/matchers/IdcMatcher.h"
#include "featloc/matchers/PcmFeatureMatcher.h"
#include "featloc/matchers/ScanMatcher.h"
#include "featloc/stereo/StableVerticalLandmarks.h"
#include "featloc/stereo/StereoLandmarkExtractor.h"

namespace featloc
{
void registerClasses()
{
	static std::once_flag once;
	std::call_once(once, [] {
		mrpt::poses::registerAllClasses_mrpt_poses();
		mrpt::obs::registerAllClasses_mrpt_obs();
		mrpt::maps::registerAllClasses_mrpt_maps();
		mrpt::opengl::registerAllClasses_mrpt_opengl();

		mrpt::rtti::registerClass(CLASS_ID(ScanMatcher));
		mrpt::rtti::registerClass(CLASS_ID(IcpMatcher));
		mrpt::rtti::registerClass(CLASS_ID(PcmFeatureMatcher));
		mrpt::rtti::registerClass(CLASS_ID(IdcMatcher));
		mrpt::rtti::registerClass(CLASS_ID(CfIdcMatcher));

		mrpt::rtti::registerClass(CLASS_ID(StereoLandmarkExtractor));
		mrpt::rtti::registerClass(CLASS_ID(StableVerticalLandmarks));

		mrpt::rtti::registerClass(CLASS_ID(PoseEstimator));
		mrpt::rtti::registerClass(CLASS_ID(OdometryEstimator));
		mrpt::rtti::registerClass(CLASS_ID(MatcherChainEstimator));
		mrpt::rtti::registerClass(CLASS_ID(EkfEstimator));

		// featloc's sensor plugin, for featloc-live's driver = TcpOdometrySensor.
		TcpOdometrySensor::doRegister();
	});
}
}  // namespace featloc
