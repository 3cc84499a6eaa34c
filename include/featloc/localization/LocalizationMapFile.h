#pragma once
#include "featloc/localization/LocalizationMap.h"
#include "featloc/localization/LocalizationOptions.h"

namespace featloc
{
/** Reads `[Localization] map` into a LocalizationMap, by the file's
 * extension:
 * - `.simplemap(.gz)`: MRPT's CSimpleMap (keyframe scans at their poses, as
 *   featloc-run's map.simplemap or icp-slam write it); its 2-D scans are
 *   inserted into an occupancy grid of grid_resolution (MRPT's insertion:
 *   free space along each beam, occupied at its end, so people walking
 *   through the mapping run are carved out again);
 * - `.gridmap(.gz)`: MRPT's serialized COccupancyGridMap2D, as is;
 * - `.png .pgm .bmp .jpg .jpeg`: an occupancy image with image_resolution
 *   and image_origin (COccupancyGridMap2D::loadFromBitmapFile, as
 *   pf-localization);
 * - anything else: a featloc-sim world file or a wall list (WallMapFile):
 *   its walls, polygon sides and round obstacles drawn into a grid of
 *   grid_resolution, everything else free.
 * A file that is missing, unreadable, of another class, or that holds no
 * obstacle is an InputError naming the file. */
class LocalizationMapFile
{
   public:
	static LocalizationMap load(const LocalizationOptions& options);
};
}  // namespace featloc
