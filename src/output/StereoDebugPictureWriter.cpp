#include "featloc/output/StereoDebugPictureWriter.h"
#include "featloc/core/WholeFile.h"

#include <opencv2/imgcodecs.hpp>

#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "featloc/estimators/StereoStepResult.h"
#include "featloc/output/StepRecord.h"
#include "featloc/output/StereoDebugPicture.h"
#include "featloc/io/DecodedStereoPair.h"

namespace featloc
{
StereoDebugPictureWriter::StereoDebugPictureWriter(std::string dir, unsigned int every)
	: m_dir(std::move(dir)), m_every(every)
{
	std::error_code ec;
	std::filesystem::create_directories(m_dir, ec);
	if (ec) throw std::runtime_error("cannot create '" + m_dir + "': " + ec.message());
}

void StereoDebugPictureWriter::onStep(const StepRecord& r)
{
	if (!r.stereo || !r.step.stereoImages) return;
	if (m_seen++ % m_every != 0) return;
	char name[32];
	std::snprintf(name, sizeof(name), "/%06zu.png", r.step.index);
	const std::string file = m_dir + name;
	const cv::Mat picture = StereoDebugPicture::draw(r.step.stereoImages->left, r.stereo->frame);
	writeWholeFile(file, [&](const std::string& partial) {
		if (!cv::imwrite(partial, picture)) throw std::runtime_error("cannot write '" + file + "'");
	});
}
}  // namespace featloc
