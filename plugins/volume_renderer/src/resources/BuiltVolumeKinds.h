#pragma once
// Internal to the pass: the kinds of auxiliary volume the GPU builds (light volume, opacity mip
// chain), each with its shape and build plan; the binder makes and rebuilds whichever a
// program's implementations need, naming none.
#include "BuiltVolumes.h"

#include <vector>

namespace volren {

/// One kind of GPU-built auxiliary volume: what it is, how it is shaped and how it is built.
struct BuiltVolumeKind
{
    AuxData aux;          ///< the auxiliary data it is (ShaderFunction::needs)
    const char* name;     ///< in statistics and messages ("light volume")
    const char* sampler;  ///< the sampler it is read through, left out of its own build's key
    bool readsLights;     ///< its contents depend on the lights (not only the classified volume)
    bool mipmapped;       ///< it has a full mip chain
    /// Its texels per axis for a sampled level of `levelDims` voxels.
    osg::Vec3i (*dims)(const osg::Vec3i& levelDims, const BindContext& context);
    /// Its half-float channels (1, 2 or 4).
    int (*channels)(const BindContext& context);
    /// The dispatches that build its `dims` texels over a box of `worldSize`.
    std::vector<BuildDispatch> (*plan)(const BindContext& context, const osg::Vec3d& worldSize, const osg::Vec3i& dims);
};

/// Every kind of GPU-built volume.
const std::vector<BuiltVolumeKind>& builtVolumeKinds();

/// The kind that is `aux`, or null when `aux` is not built on the GPU.
const BuiltVolumeKind* builtVolumeKind(AuxData aux);

}  // namespace volren
