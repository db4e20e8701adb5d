// Illumination implementations (one call per light from the lighting shadings).
#include <volume_renderer/ShaderFunctionRegistry.h>

#include <volume_model/RenderSettings.h>

namespace volren {

void registerIlluminationFunctions(ShaderFunctionRegistry& registry)
{
    registry.add({.slot = "Illumination", .name = "null", .traits = {.calls = SlotList{}}});
    registry.add({.slot = "Illumination", .name = "lambert", .traits = {.calls = SlotList{}}});
    registry.add({.slot = "Illumination",
                  .name = "blinn_phong",
                  .uniforms = {{"volren_specular", "float", ""}, {"volren_shininess", "float", ""}},
                  .bind =
                      [](BindContext& c) {
                          c.uniform("volren_specular", float(c.settings.specular));
                          c.uniform("volren_shininess", float(c.settings.shininess));
                      },
                  .traits = {.calls = SlotList{}, .aliases = {"blinnphong", "blinn-phong", "phong"}}});
    registry.add({.slot = "Illumination",
                  .name = "cook_torrance",
                  .uniforms = {{"volren_specular", "float", ""}, {"volren_roughness", "float", ""}},
                  .bind =
                      [](BindContext& c) {
                          c.uniform("volren_specular", float(c.settings.specular));
                          c.uniform("volren_roughness", float(c.settings.roughness));
                      },
                  .traits = {.calls = SlotList{}, .aliases = {"cooktorrance", "cook-torrance"}}});
    // Volume scattering (no normal): the phase function between the light and the view.
    registry.add({.slot = "Illumination",
                  .name = "henyey_greenstein",
                  .uniforms = {{"volren_anisotropy", "float", ""}},
                  .bind = [](BindContext& c) { c.uniform("volren_anisotropy", float(c.settings.anisotropy)); },
                  .traits = {.calls = SlotList{}, .aliases = {"hg", "phase", "henyeygreenstein", "scattering"}}});
}

}  // namespace volren
