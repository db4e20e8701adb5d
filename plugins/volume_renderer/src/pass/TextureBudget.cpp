#include "TextureBudget.h"

#include <volume_renderer/GraphicsDriver.h>
#include <volume_renderer/VolumeMipChain.h>

#include <algorithm>

namespace volren {

bool exceedsTextureBudget(const VolumeNode& node, int lod, bool coarseByteFiltering)
{
    const Volume& volume = *node.getVolume();
    if (volume.fullResolution()) return true;  // a lazy volume's finer levels are on disk: bricks only
    const osg::Vec3i d = mipDims(volume.dims(), lod);
    const std::string& precision = node.settings.texturePrecision;
    const bool wide = voxelSize(volume.type()) == 1 && (precision == "16bit" || (precision == "auto" && coarseByteFiltering));
    const std::size_t bytes = std::size_t(d.x()) * std::size_t(d.y()) * std::size_t(d.z()) * (wide ? 2 : voxelSize(volume.type()));
    return bytes > volumeMemoryBudget(node.settings) || exceedsLargest3DTexture(d);
}

}  // namespace volren
