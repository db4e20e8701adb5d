#pragma once

namespace volren {

class VolumeNode;

/// Most samples one ray may take; finer settings are coarsened to this, with a warning.
constexpr double maxStepsPerRay = double(1 << 22);

/// Step in world units for `node`: its setting (a distance, or a factor of the smallest voxel
/// spacing), bounded so that no ray through its box takes more than maxStepsPerRay samples.
double effectiveSampleDistance(const VolumeNode& node);

}  // namespace volren
