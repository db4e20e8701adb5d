// Shadowing implementations: the fraction of a light that reaches a sample.
#include "CommonBindings.h"

#include <volume_renderer/ShaderFunctionRegistry.h>

#include <volume_model/RenderSettings.h>
#include <volume_model/Volume.h>

#include <osg/Texture3D>

#include <algorithm>
#include <cmath>

namespace volren {

using bindings::operator+;

void registerShadowingFunctions(ShaderFunctionRegistry& registry)
{
    registry.add({.slot = "Shadowing", .name = "null", .traits = {.calls = SlotList{}}});

    // Shadow rays: a march towards each light per lit sample, with the view ray's sampling.
    registry.add({.slot = "Shadowing",
                  .name = "ray",
                  .uniforms = bindings::geometry + std::vector<UniformDecl>{{"volren_shadowStep", "float", ""},
                                                                            {"volren_referenceStep", "float", ""},
                                                                            {"volren_shadowCutoffDepth", "float", ""}},
                  .bind =
                      [](BindContext& c) {
                          bindings::bindGeometry(c);
                          c.uniform("volren_shadowStep", float(c.sampleDistance * c.settings.shadowStepFactor));
                          c.uniform("volren_referenceStep", float(c.volume.minSpacing()));
                          const double cutoff = c.settings.shadowCutoff;
                          c.uniform("volren_shadowCutoffDepth", float(cutoff > 0.0 ? -std::log(cutoff) : 1e30));
                      },
                  .traits = {.calls = SlotList{"Reconstruction", "Classification", "ClipPosition"},
                             .clipsPerSample = true,
                             .shadows = true,
                             .aliases = {"shadowray", "shadow_ray", "rays"}}});

    // Propagated light volume: each light's transmittance in a half-float volume, built on the GPU
    // slice by slice (light_volume_build.comp) whenever the light, the TF, the volume or a clip
    // shape changes, read with one trilinear fetch per lit sample.
    registry.add({.slot = "Shadowing",
                  .name = "light_volume",
                  .buildFile = "Shadowing/light_volume_build.comp",
                  .uniforms = bindings::geometry + bindings::lights +
                              std::vector<UniformDecl>{{"volren_shadowStep", "float", ""}, {"volren_referenceStep", "float", ""}},
                  .textures = {{"volren_lightVolume", "sampler3D"}},
                  .needs = {AuxData::LightVolume},
                  .bind =
                      [](BindContext& c) {
                          bindings::bindGeometry(c);
                          // The build integrates the full-resolution classification along each
                          // path at the view ray's step (times the shadow step factor).
                          c.uniform("volren_shadowStep", float(c.sampleDistance * c.settings.shadowStepFactor));
                          c.uniform("volren_referenceStep", float(c.volume.minSpacing()));
                          c.texture("volren_lightVolume", c.aux.at(AuxData::LightVolume).get());
                      },
                  .traits = {.calls = SlotList{"Reconstruction", "Classification", "ClipPosition"},
                             .clipsPerSample = true,
                             .shadows = true,
                             .aliases = {"lightvolume", "light-volume", "propagated"}}});

    // Cone tracing through the opacity mip chain: soft shadows (cone), and with directional
    // ambient occlusion (cone_ao). The chain is built on the GPU (cone_build.comp, then
    // box-filtered levels) when the TF, the volume or a clip shape changes; lights are free.
    const std::vector<UniformDecl> coneUniforms =
        bindings::geometry + std::vector<UniformDecl>{{"volren_shadowStep", "float", ""},
                                                      {"volren_referenceStep", "float", ""},
                                                      {"volren_shadowCutoffDepth", "float", ""},
                                                      {"volren_coneVoxel", "float", ""},
                                                      {"volren_coneAngle", "float", ""},
                                                      {"volren_coneStart", "float", ""},
                                                      {"volren_coneStepGrowth", "float", ""},
                                                      {"volren_coneFilterSigma", "float", ""},
                                                      {"volren_aoDistance", "float", ""}};
    auto bindCone = [](BindContext& c) {
        bindings::bindGeometry(c);
        c.uniform("volren_shadowStep", float(c.sampleDistance * c.settings.shadowStepFactor));
        c.uniform("volren_referenceStep", float(c.volume.minSpacing()));
        const double cutoff = c.settings.shadowCutoff;
        c.uniform("volren_shadowCutoffDepth", float(cutoff > 0.0 ? -std::log(cutoff) : 1e30));
        // One voxel of the chain's finest level (the sampled level), its smallest extent.
        const osg::Vec3d size = c.volume.worldSize();
        const osg::Texture3D& chain = static_cast<const osg::Texture3D&>(*c.aux.at(AuxData::OpacityMipChain));
        const double voxel = std::min({size.x() / chain.getTextureWidth(), size.y() / chain.getTextureHeight(),
                                       size.z() / chain.getTextureDepth()});
        c.uniform("volren_coneVoxel", float(voxel));
        c.uniform("volren_coneAngle", float(osg::DegreesToRadians(c.settings.coneAngle)));
        c.uniform("volren_coneStart", float(c.settings.coneStart));
        c.uniform("volren_coneStepGrowth", float(c.settings.coneStepGrowth));
        c.uniform("volren_coneFilterSigma", float(c.settings.coneFilterSigma));
        c.uniform("volren_aoDistance", float(c.settings.aoDistance * voxel));
        c.texture("volren_opacityMips", c.aux.at(AuxData::OpacityMipChain).get());
    };
    for (const char* name : {"cone", "cone_ao"})
        registry.add({.slot = "Shadowing",
                      .name = name,
                      .buildFile = "Shadowing/cone_build.comp",
                      .includes = {"Shadowing/cone_march.glsl"},
                      .uniforms = coneUniforms,
                      .textures = {{"volren_opacityMips", "sampler3D"}},
                      .needs = {AuxData::OpacityMipChain},
                      .bind = bindCone,
                      .traits = {.calls = SlotList{"Reconstruction", "Classification", "ClipPosition"},
                                 .clipsPerSample = true,
                                 .shadows = true,
                                 .occlusion = std::string(name) == "cone_ao",
                                 .aliases = std::string(name) == "cone" ? std::vector<std::string>{"cones", "cone_shadows"}
                                                                        : std::vector<std::string>{"cones_ao", "cone+ao"}}});
}

}  // namespace volren
