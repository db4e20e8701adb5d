#pragma once
#include <osg/Vec3i>

#include <cstddef>
#include <string>

namespace volren {

/// What one propagated light volume (Shadowing light_volume) holds and what building it cost.
struct LightVolumeStatistics
{
    std::string node;               ///< the VolumeNode's name
    osg::Vec3i dims;                ///< texels per axis
    int channels = 0;               ///< lights stored (one half-float channel each; 3 lights use 4)
    std::size_t bytes = 0;          ///< texture storage
    unsigned int builds = 0;        ///< builds so far
    double lastBuildSeconds = 0.0;  ///< wall time of the last build, the GPU finished before and after
};

}  // namespace volren
