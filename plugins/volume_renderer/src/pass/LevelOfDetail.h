#pragma once
// Internal to the pass: which mip level a volume is sampled from in this cull.
#include "SceneAnalysis.h"

#include <osgUtil/CullVisitor>

namespace volren {

/// The node's `lod` setting, plus with `lodByDistance` the whole levels by which one pixel
/// outgrows a voxel where the volume's box is nearest the camera (log2 of the voxels a pixel
/// covers there, rounded down; none with the camera inside the box), at most the last level of
/// the volume's mip chain.
int levelOfDetail(const VolumeCandidate& candidate, osgUtil::CullVisitor& cv);

}  // namespace volren
