#pragma once
#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/poses/CPosePDFGaussian.h>
#include <mrpt/rtti/CObject.h>
#include <opencv2/core/mat.hpp>

#include <string>

#include "featloc/stereo/StereoHead.h"
#include "featloc/stereo/StereoLandmarkFrame.h"

namespace featloc
{
/** Base of the stereo landmark extractors: turns one rectified stereo pair
 * and the robot's pose estimate into modelled landmarks.
 *
 * Extractors are MRPT RTTI classes created by name from the configuration
 * (`[StereoLandmarks] class = featloc::StableVerticalLandmarks`), reading
 * their parameters from their own section, like the scan matchers. */
class StereoLandmarkExtractor : public mrpt::rtti::CObject
{
	DEFINE_VIRTUAL_MRPT_OBJECT(StereoLandmarkExtractor)

   public:
	~StereoLandmarkExtractor() override = default;

	/** Throws ConfigError on a bad value, InputError on a bad map file. */
	virtual void loadParams(const mrpt::config::CConfigFileBase& cfg, const std::string& section) = 0;
	/** For the extractor a run uses (not for sections only validated):
	 * throws ConfigError when a required key was left empty. */
	virtual void requireComplete(const mrpt::config::CConfigFileBase&, const std::string&) const {}
	virtual void saveParams(mrpt::config::CConfigFileBase& cfg, const std::string& section) const = 0;

	/** One pair: grey CV_8U images of equal size, the head's geometry,
	 * the robot pose (world frame) with its covariance. */
	virtual StereoLandmarkFrame process(
		const cv::Mat& left, const cv::Mat& right, const StereoHead& head,
		const mrpt::poses::CPosePDFGaussian& robot) const = 0;

	std::string className() const;
	/** Name of map wall `wall` (the reference plane of a landmark). */
	virtual std::string planeName(size_t wall) const { return "wall " + std::to_string(wall); }
	/** The map file the extractor reads ("" if none), for messages. */
	virtual std::string mapFile() const { return ""; }
};
}  // namespace featloc
