// Shadowing implementations: the fraction of a light that reaches a sample.
#include "CommonBindings.h"

#include <volume_renderer/ShaderFunctionRegistry.h>

#include <volume_model/RenderSettings.h>
#include <volume_model/Volume.h>

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
                             .aliases = {"lightvolume", "light-volume", "propagated"}}});
}

}  // namespace volren
