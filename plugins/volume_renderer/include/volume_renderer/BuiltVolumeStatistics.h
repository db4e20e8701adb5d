#pragma once
#include <osg/Vec3i>

#include <cstddef>
#include <string>

namespace volren {

/// What one auxiliary volume built on the GPU (a light volume, an opacity mip chain) holds and
/// what building it cost.
struct BuiltVolumeStatistics
{
    std::string node;               ///< the VolumeNode's name
    std::string kind;               ///< "light volume" or "opacity mip chain"
    osg::Vec3i dims;                ///< texels per axis of its finest level
    int channels = 0;               ///< half-float channels per texel (a light volume: one per light, 3 use 4)
    std::size_t bytes = 0;          ///< texture storage, every level
    std::size_t volumeVoxels = 0;   ///< voxels of the node's volume (bytes per voxel = bytes / this)
    unsigned int builds = 0;        ///< builds so far
    double lastBuildSeconds = 0.0;  ///< wall time of the last build, the GPU finished before and after
};

}  // namespace volren
