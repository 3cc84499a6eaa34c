#pragma once
#include <string>

#include "featloc/output/RunOutput.h"

namespace featloc
{
/** `[Output] stereo_debug_every = N`: DIR/<step>.png, the left image of
 * every N-th processed stereo pair drawn by StereoDebugPicture (Moon,
 * Miura & Shirai's Figs. 5-6). */
class StereoDebugPictureWriter : public RunOutput
{
   public:
	StereoDebugPictureWriter(std::string dir, unsigned int every);
	void onStep(const StepRecord& record) override;
	void finish(const RunStats&) override {}
	std::string path() const override { return m_dir; }

   private:
	std::string m_dir;
	unsigned int m_every;
	size_t m_seen = 0;
};
}  // namespace featloc
