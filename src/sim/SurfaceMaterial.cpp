#include "featloc/sim/SurfaceMaterial.h"

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>

namespace featloc
{
namespace
{
constexpr int kTile = 256;

enum class Pattern
{
	Noise,	//!< filtered Gaussian noise
	Poster,	 //!< flat printed blocks over noise
	Books,	//!< vertical spines of random width and shade, shelf boards
	Tiles	//!< floor tiles with grout lines
};

struct Spec
{
	const char* name;
	Pattern pattern;
	double mean;  //!< [grey level]
	double contrast;  //!< [grey level] std of the noise
	double grainU, grainV;	//!< [m] blur sigma of the noise along u, v
	double texel;  //!< [m]
};

// Grey levels and grain sizes chosen to look like the surfaces of the
// papers' scenes: paints nearly flat (a block matcher finds little there),
// fabric and prints rich in texture.
const Spec kSpecs[] = {
	{"plain", Pattern::Noise, 170, 3, 0.004, 0.004, 0.004},
	{"paint", Pattern::Noise, 185, 2.5, 0.004, 0.004, 0.004},
	{"painted_white", Pattern::Noise, 205, 2.5, 0.004, 0.004, 0.004},
	{"corridor_grey", Pattern::Noise, 160, 3, 0.004, 0.004, 0.004},
	{"ceiling", Pattern::Noise, 220, 2, 0.006, 0.006, 0.006},
	{"whiteboard", Pattern::Noise, 232, 1.5, 0.004, 0.004, 0.004},
	{"paper", Pattern::Noise, 240, 4, 0.002, 0.002, 0.002},
	{"partition", Pattern::Noise, 120, 16, 0.003, 0.003, 0.003},
	{"wood", Pattern::Noise, 120, 18, 0.004, 0.03, 0.004},
	{"metal", Pattern::Noise, 150, 5, 0.01, 0.01, 0.005},
	{"metal_grey", Pattern::Noise, 140, 5, 0.01, 0.01, 0.005},
	{"concrete", Pattern::Noise, 140, 14, 0.005, 0.005, 0.004},
	{"poster", Pattern::Poster, 110, 30, 0.008, 0.008, 0.004},
	{"books", Pattern::Books, 110, 6, 0.002, 0.002, 0.004},
	{"door_frame", Pattern::Noise, 60, 4, 0.004, 0.004, 0.004},
	{"ink", Pattern::Noise, 45, 3, 0.002, 0.002, 0.002},
	{"clothes", Pattern::Noise, 80, 25, 0.006, 0.006, 0.004},
	{"plant", Pattern::Noise, 90, 40, 0.01, 0.01, 0.004},
	{"floor", Pattern::Tiles, 115, 12, 0.004, 0.004, 0.004},
};

// FNV-1a: a seed from the name that does not depend on the standard library.
uint64_t nameSeed(const std::string& s)
{
	uint64_t h = 1469598103934665603ull;
	for (unsigned char c : s) h = (h ^ c) * 1099511628211ull;
	return h;
}

cv::Mat periodicNoise(cv::RNG& rng, double sigmaU, double sigmaV)
{
	cv::Mat n(kTile, kTile, CV_32F);
	rng.fill(n, cv::RNG::NORMAL, 0.0, 1.0);
	if (sigmaU < 0.3 && sigmaV < 0.3) return n;
	// Blur a 3x3 tiling and keep the centre: the result wraps seamlessly.
	const int pad = static_cast<int>(std::ceil(4 * std::max(sigmaU, sigmaV))) + 1;
	cv::Mat big;
	cv::copyMakeBorder(n, big, pad, pad, pad, pad, cv::BORDER_WRAP);
	cv::GaussianBlur(big, big, cv::Size(0, 0), std::max(sigmaU, 0.3), std::max(sigmaV, 0.3));
	cv::Mat out = big(cv::Rect(pad, pad, kTile, kTile)).clone();
	cv::Scalar mean, sd;
	cv::meanStdDev(out, mean, sd);
	out = (out - mean[0]) / std::max(sd[0], 1e-9);
	return out;
}

cv::Mat makeTile(const Spec& s)
{
	cv::RNG rng(nameSeed(s.name));
	cv::Mat noise = periodicNoise(rng, s.grainU / s.texel, s.grainV / s.texel);
	cv::Mat tile = noise * s.contrast + s.mean;
	if (s.pattern == Pattern::Poster)
	{
		// A print: overlapping flat blocks (text lines, pictures) whose
		// borders are sharp edges in both directions.
		for (int i = 0; i < 40; i++)
		{
			const int w = rng.uniform(8, 90), h = rng.uniform(4, 60);
			const int x = rng.uniform(0, kTile - w), y = rng.uniform(0, kTile - h);
			const double g = rng.uniform(20.0, 235.0);
			cv::Mat roi = tile(cv::Rect(x, y, w, h));
			roi = roi * 0.25 + 0.75 * g;
		}
	}
	else if (s.pattern == Pattern::Books)
	{
		// Spines 2-6 cm wide, each its own shade; a shelf board every 32
		// cm (80 texels) hides a band of them.
		for (int x = 0; x < kTile;)
		{
			const int w = std::min(rng.uniform(5, 16), kTile - x);
			const double g = rng.uniform(30.0, 210.0);
			cv::Mat roi = tile(cv::Rect(x, 0, w, kTile));
			roi = roi + (g - s.mean);
			x += w;
		}
		for (int y = 0; y < kTile; y += 80)
			tile(cv::Rect(0, y, kTile, std::min(6, kTile - y))).setTo(cv::Scalar(185));
	}
	else if (s.pattern == Pattern::Tiles)
	{
		// Half-metre tiles with 8 mm grout lines.
		for (int k = 0; k < kTile; k += kTile / 2)
		{
			tile(cv::Rect(k, 0, 2, kTile)).setTo(cv::Scalar(70));
			tile(cv::Rect(0, k, kTile, 2)).setTo(cv::Scalar(70));
		}
	}
	cv::min(tile, 255.0, tile);
	cv::max(tile, 0.0, tile);
	return tile;
}
}  // namespace

class SurfaceMaterialBuilder
{
   public:
	static std::shared_ptr<const SurfaceMaterial> build(const Spec& s)
	{
		std::shared_ptr<SurfaceMaterial> m(new SurfaceMaterial());
		m->m_name = s.name;
		m->m_texel = s.texel;
		cv::Mat level = makeTile(s);
		while (true)
		{
			SurfaceMaterial::Level l;
			l.size = level.cols;
			cv::Mat columnMajor = level.t();
			l.texels.assign(columnMajor.ptr<float>(0), columnMajor.ptr<float>(0) + columnMajor.total());
			m->m_levels.push_back(std::move(l));
			if (level.cols == 1) break;
			cv::Mat half;
			cv::resize(level, half, cv::Size(level.cols / 2, level.rows / 2), 0, 0, cv::INTER_AREA);
			level = half;
		}
		return m;
	}
};

std::shared_ptr<const SurfaceMaterial> SurfaceMaterial::byName(const std::string& name)
{
	static std::mutex mutex;
	static std::map<std::string, std::shared_ptr<const SurfaceMaterial>> cache;
	std::lock_guard<std::mutex> lock(mutex);
	if (auto it = cache.find(name); it != cache.end()) return it->second;
	for (const auto& s : kSpecs)
		if (name == s.name) return cache[name] = SurfaceMaterialBuilder::build(s);
	return nullptr;
}

std::vector<std::string> SurfaceMaterial::names()
{
	std::vector<std::string> out;
	for (const auto& s : kSpecs) out.emplace_back(s.name);
	return out;
}

int SurfaceMaterial::levelFor(double footprint) const
{
	if (!(footprint > m_texel)) return 0;
	const int l = static_cast<int>(std::lround(std::log2(footprint / m_texel)));
	return std::clamp(l, 0, static_cast<int>(m_levels.size()) - 1);
}
}  // namespace featloc
