#pragma once
// Internal to the pass: the build plan of an opacity mip chain (Shadowing cone, cone_ao),
// the auxiliary data kind "opacity mip chain" (declared in functions/Shadowing.cpp).
#include <volume_renderer/AuxKind.h>
#include <volume_renderer/BindContext.h>

#include <vector>

namespace volren {

/// The dispatches that build an opacity mip chain of `dims` texels (Shadowing/cone_build.comp,
/// 4 x 4 x 4 invocations per group): every texel of the finest level, then each level above as
/// the box filter (2 x 2 x 2 mean) of the one below, up to 1 x 1 x 1.
std::vector<BuildDispatch> opacityVolumePlan(const osg::Vec3i& dims);

}  // namespace volren
