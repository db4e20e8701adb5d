#pragma once
// Internal to the pass: the shape and build plan of a propagated light volume (Shadowing
// light_volume), the auxiliary data kind "light volume" (declared in functions/Shadowing.cpp).
#include <volume_renderer/AuxKind.h>
#include <volume_renderer/BindContext.h>

#include <vector>

namespace volren {

/// Lights a light volume holds (one channel each, four per layer); further lights get none.
constexpr int lightVolumeMaxLights = 8;

/// Layers of a light volume for `lights` lights, stacked along z: lights 0-3 in the first, 4-7
/// in the second (its texture is that many times as deep).
int lightVolumeLayers(std::size_t lights);

/// `light` (node coordinates) in the texture space of a box of `worldSize` centred on the node's
/// origin: a point light's position (w = 1), or a directional light's direction (w = 0).
osg::Vec4d lightInTextureSpace(const LightInfo& light, const osg::Vec3d& worldSize);

/// The texels per axis of the light volume of a volume of `dims` voxels at `scale` (0, 1]:
/// each axis scaled and rounded, at least 2.
osg::Vec3i lightVolumeDims(const osg::Vec3i& dims, double scale);

/// Half-float channels of a light volume for `lights` lights: one each up to four (3 use 4), 4
/// with two layers.
int lightVolumeChannels(std::size_t lights);

/// The dispatches that build a light volume of `texture` texels (all layers) for the first eight `lights` (node
/// coordinates) over a box of `worldSize` (Shadowing/light_volume_build.comp): per light, one
/// dispatch per slice along the axis where the light's direction advances most in texels, each
/// slice after its neighbour towards the light.
std::vector<BuildDispatch> lightVolumePlan(const std::vector<LightInfo>& lights, const osg::Vec3d& worldSize,
                                           const osg::Vec3i& texture);

}  // namespace volren
