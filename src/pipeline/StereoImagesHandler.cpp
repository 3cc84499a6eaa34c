#include "featloc/pipeline/StereoImagesHandler.h"

#include <mrpt/obs/CObservationStereoImages.h>
#include <opencv2/imgcodecs.hpp>

#include <cmath>
#include <filesystem>

#include "featloc/core/AllocationCeiling.h"
#include "featloc/core/InputError.h"
#include "featloc/io/DecodedStereoPair.h"

namespace featloc
{
namespace
{
std::string sizeText(int w, int h) { return std::to_string(w) + "x" + std::to_string(h); }

/** Larger calibrated images than this are taken for corrupt values, not
 * cameras: 16384 pixels a side, 2^28 pixels (a 268-megapixel sensor). */
constexpr uint32_t kMaxImageSide = 16384;
constexpr uint64_t kMaxImagePixels = uint64_t(1) << 28;

/** What decoding an image of the calibrated size may take: 4 bytes per
 * channel of 3 channels, and OpenCV's working buffers. */
uint64_t decodeBudget(const mrpt::img::TCamera& c)
{
	return 16 * uint64_t(c.ncols) * uint64_t(c.nrows) + (uint64_t(64) << 20);
}

/** The image, grey, loading it from its file when it is stored externally
 * (the path made absolute in the observation on success). */
cv::Mat checkImage(
	mrpt::img::CImage& img, const char* side, const std::string& imagesDir,
	const mrpt::img::TCamera& camera, const std::string& where)
{
	if (!img.isExternallyStored())
	{
		if (img.isEmpty())
			throw InputError(where + ": the " + side + " image of the stereo pair is empty");
		return img.grayscale().asCvMat<cv::Mat>(mrpt::img::DEEP_COPY);
	}
	namespace fs = std::filesystem;
	fs::path file(img.getExternalStorageFile());
	if (file.is_relative()) file = fs::path(imagesDir) / file;
	std::error_code ec;
	if (!fs::is_regular_file(file, ec))
		throw InputError(
			where + ": the " + side + " image file '" + file.string() +
			"' is missing (external images are looked up in the rawlog's " +
			"<name>_Images folder: '" + imagesDir + "')");
	// An image file's header can claim any size; the decoder allocates it
	// before reading the pixels. The calibration says what size to expect.
	cv::Mat m;
	std::string failure;
	try
	{
		const AllocationCeiling ceiling(decodeBudget(camera));
		m = cv::imread(file.string(), cv::IMREAD_GRAYSCALE);
	}
	catch (const std::exception& e)	 // std::bad_alloc, cv::Exception
	{
		failure = e.what();
	}
	if (m.empty())
		throw InputError(
			where + ": the " + side + " image file '" + file.string() +
			"' does not decode as an image within " +
			std::to_string(decodeBudget(camera) >> 20) + " MiB (the calibration is for " +
			sizeText(static_cast<int>(camera.ncols), static_cast<int>(camera.nrows)) + ")" +
			(failure.empty() ? std::string() : ": " + failure));
	img.setExternalStorage(fs::absolute(file, ec).string());
	return m;
}

void checkCamera(const mrpt::img::TCamera& c, const char* side, const std::string& where)
{
	const bool ok = std::isfinite(c.fx()) && std::isfinite(c.fy()) && c.fx() > 0 && c.fy() > 0 &&
		std::isfinite(c.cx()) && std::isfinite(c.cy()) && c.ncols > 0 && c.nrows > 0;
	if (ok && (c.ncols > kMaxImageSide || c.nrows > kMaxImageSide ||
				  uint64_t(c.ncols) * c.nrows > kMaxImagePixels))
		throw InputError(
			where + ": the " + side + "Camera calibration is for " +
			sizeText(static_cast<int>(c.ncols), static_cast<int>(c.nrows)) +
			" images: corrupt (at most " + std::to_string(kMaxImageSide) +
			" pixels a side and " + std::to_string(kMaxImagePixels >> 20) + " megapixels)");
	if (!ok)
		throw InputError(
			where + ": stereo observation without a calibration: " + side +
			"Camera needs focal lengths > 0 and an image size (fx " + std::to_string(c.fx()) +
			", fy " + std::to_string(c.fy()) + ", " +
			sizeText(static_cast<int>(c.ncols), static_cast<int>(c.nrows)) + ")");
}
}  // namespace

StereoImagesHandler::StereoImagesHandler(std::string imagesDirectory)
	: m_imagesDirectory(std::move(imagesDirectory))
{
}

const mrpt::rtti::TRuntimeClassId* StereoImagesHandler::observationClass() const
{
	return CLASS_ID(mrpt::obs::CObservationStereoImages);
}

bool StereoImagesHandler::handle(
	const mrpt::obs::CObservation::Ptr& o, size_t, const std::string& w,
	ObservationContribution& out)
{
	auto obs = std::dynamic_pointer_cast<mrpt::obs::CObservationStereoImages>(o);
	const std::string where = w + " (stereo '" + obs->sensorLabel + "')";
	if (obs->timestamp == INVALID_TIMESTAMP)
		throw InputError(where + ": the stereo observation has no valid timestamp");
	if (!obs->hasImageRight)
		throw InputError(where + ": the stereo observation has no right image");
	// MRPT 2.5.8 loads a default 640x480 calibration (fx 200) when none
	// was set; a zero size or focal length is what a missing one looks like
	// after deserialisation of a hand-made observation.
	checkCamera(obs->leftCamera, "left", where);
	checkCamera(obs->rightCamera, "right", where);
	const auto& rp = obs->rightCameraPose;
	const double baseline = std::sqrt(rp.x() * rp.x() + rp.y() * rp.y() + rp.z() * rp.z());
	if (!std::isfinite(baseline) || baseline <= 0)
		throw InputError(
			where + ": stereo observation without a calibration: rightCameraPose gives no "
					"baseline (the right camera must be offset from the left one)");
	auto images = std::make_shared<DecodedStereoPair>();
	images->left = checkImage(obs->imageLeft, "left", m_imagesDirectory, obs->leftCamera, where);
	images->right =
		checkImage(obs->imageRight, "right", m_imagesDirectory, obs->rightCamera, where);
	const cv::Size left = images->left.size(), right = images->right.size();
	if (left != right)
		throw InputError(
			where + ": left image " + sizeText(left.width, left.height) + " and right image " +
			sizeText(right.width, right.height) + " differ in size");
	const auto& lc = obs->leftCamera;
	if (left.width != static_cast<int>(lc.ncols) || left.height != static_cast<int>(lc.nrows))
		throw InputError(
			where + ": the images are " + sizeText(left.width, left.height) +
			" but the calibration (leftCamera) is for " +
			sizeText(static_cast<int>(lc.ncols), static_cast<int>(lc.nrows)));
	out.stereo = obs;
	out.stereoImages = images;
	m_pairs++;
	return true;
}
}  // namespace featloc
