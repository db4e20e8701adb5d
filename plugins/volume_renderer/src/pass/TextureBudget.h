#pragma once
// Internal to the pass: whether a volume's sampled level fits one 3D texture within its budget.
#include <volume_model/VolumeNode.h>

namespace volren {

/// True when mip level `lod` of the node's volume, as the texture it would be (16-bit texels of
/// 8-bit data where `coarseByteFiltering` and texturePrecision say so), exceeds the node's memory
/// budget (volumeMemoryBudget) or the largest 3D texture: the volume is then drawn from bricks.
bool exceedsTextureBudget(const VolumeNode& node, int lod, bool coarseByteFiltering);

}  // namespace volren
