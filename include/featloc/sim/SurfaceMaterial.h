#pragma once
#include <memory>
#include <string>
#include <vector>

namespace featloc
{
/** What a surface looks like to the simulated camera: a periodic grey
 * texture tile (256 x 256 texels of `texelSize` metres) generated from the
 * material's name alone, so every run and every machine renders the same
 * pixels. Kept as a mip pyramid (each level the 2x2 average of the one
 * below) so that a distant surface is sampled without aliasing, which
 * would make the two images of a pair disagree.
 *
 * The catalogue (doc/simulator.md, "Stereo camera"): low-texture paints
 * (`plain`, `paint`, `painted_white`, `corridor_grey`, `ceiling`), the
 * `whiteboard`, `paper`, fabric `partition`, `wood`, `metal`,
 * `metal_grey`, `concrete`, printed `poster`, marker `ink`, `books` (vertical spines of
 * random width and shade: a shelf), `door_frame`, `clothes`, `plant`
 * and the tiled `floor`. */
class SurfaceMaterial
{
   public:
	/** The catalogue's material; nullptr for an unknown name. Built on
	 * first use, shared and immutable after (thread-safe). */
	static std::shared_ptr<const SurfaceMaterial> byName(const std::string& name);
	static std::vector<std::string> names();

	const std::string& name() const { return m_name; }
	double texelSize() const { return m_texel; }	//!< [m] at level 0

	/** One mip level: side length (power of two) and texels,
	 * column-major (texels[u * size + v]: a renderer walking down an image
	 * column of a wall reads contiguous memory). */
	struct Level
	{
		int size = 0;
		std::vector<float> texels;
	};
	const Level& level(int i) const { return m_levels[static_cast<size_t>(i)]; }
	/** The level whose texels are about `footprint` metres wide. */
	int levelFor(double footprint) const;

   private:
	SurfaceMaterial() = default;
	std::string m_name;
	double m_texel = 0.004;
	std::vector<Level> m_levels;

	friend class SurfaceMaterialBuilder;
};
}  // namespace featloc
