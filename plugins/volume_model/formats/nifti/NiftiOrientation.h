#pragma once
#include "NiftiHeader.h"

#include <osg/Matrixd>

namespace volren::nifti {

/// Key of the osg::Matrixd user value on the Volume: voxel index (i, j, k) to NIfTI world
/// coordinates (RAS+, usually mm), OSG row-vector convention: world = Vec3d(i, j, k) * matrix.
constexpr const char* voxelToWorldKey = "voxelToWorld";
/// Key of the std::string user value naming the source of that matrix: "sform", "qform" or "pixdim".
constexpr const char* voxelToWorldSourceKey = "voxelToWorldSource";

/// Voxel-to-world matrix of `h` as the NIfTI standard defines it: the sform when
/// sform_code > 0, else the qform (quaternion, qfac, offsets) when qform_code > 0, else the
/// plain pixdim scaling. `source` receives "sform", "qform" or "pixdim".
osg::Matrixd voxelToWorld(const NiftiHeader& h, std::string& source);

}  // namespace volren::nifti
