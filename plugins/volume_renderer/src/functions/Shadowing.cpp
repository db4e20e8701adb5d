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
}

}  // namespace volren
