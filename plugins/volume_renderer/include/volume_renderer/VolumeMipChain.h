#pragma once
#include <volume_model/Volume.h>

#include <osg/Image>

#include <vector>

namespace volren {

/// Voxels along each axis at mip level `level` of a volume of `dims`: halved `level` times,
/// rounded down, at least 1 (OpenGL's sizes, so the GPU's levels are these).
osg::Vec3i mipDims(const osg::Vec3i& dims, int level);

/// Levels of a full mip chain of a volume of `dims`, level 0 included (down to 1 x 1 x 1).
int mipLevelCount(const osg::Vec3i& dims);

/// Level-0 voxels (along the axis where they are most) that one voxel of `level` covers.
double mipVoxelSpan(const osg::Vec3i& dims, int level);

/// Levels 1 .. `levels` of block (0, 0) of `volume`'s mip chain, each an image of its own in
/// the stored voxel type (the texture a level of detail samples). Each voxel of level L+1 is the
/// average of the level-L voxels its box covers, with fractional weights where an odd size
/// halves (so it is a convex combination of the voxels below it: value ranges of finer levels
/// bound coarser ones); NaN voxels are left out (NaN where a box holds only NaN); integers are
/// rounded. `levels` is clamped to the chain (mipLevelCount - 1).
std::vector<osg::ref_ptr<osg::Image>> mipLevelImages(const Volume& volume, int levels);

}  // namespace volren
