// Shading implementations.
#include "CommonBindings.h"

#include <volume_renderer/ShaderFunctionRegistry.h>

#include <volume_model/RenderSettings.h>

namespace volren {

namespace {

using bindings::operator+;

/// A shading lit by the scene's lights through the chosen Illumination (Shading/lights.glsl).
ShaderFunction lit(const std::string& name, std::vector<UniformDecl> extra = {})
{
    return {.slot = "Shading",
            .name = name,
            .includes = {"Shading/lights.glsl"},
            .uniforms = bindings::geometry + bindings::lights + extra,
            .bind =
                [](BindContext& c) {
                    bindings::bindGeometry(c);
                    bindings::bindLights(c);
                },
            .traits = {.calls = SlotList{"Gradient", "Illumination", "Shadowing"},
                       .required = {"Illumination"},
                       .lights = LightUse::Required}};
}

}  // namespace

void registerShadingFunctions(ShaderFunctionRegistry& registry)
{
    registry.add({.slot = "Shading", .name = "null", .traits = {.calls = SlotList{}}});
    registry.add(lit("lighting"));

    ShaderFunction threshold = lit("lighting_threshold", {{"volren_shadingThreshold", "float", ""}});
    threshold.bind = [](BindContext& c) {
        bindings::bindGeometry(c);
        bindings::bindLights(c);
        c.uniform("volren_shadingThreshold", float(c.settings.shadingThreshold));
    };
    registry.add(threshold);

    // Lit on boundaries only, weighted by the gradient magnitude against volren_gradientScale.
    ShaderFunction surface = lit("lighting_surface", {bindings::gradientScale});
    surface.bind = [](BindContext& c) {
        bindings::bindGeometry(c);
        bindings::bindLights(c);
        bindings::bindGradientScale(c);
    };
    registry.add(surface);

    registry.add({.slot = "Shading",
                  .name = "debug",
                  .uniforms = bindings::geometry + bindings::lights +
                              std::vector<UniformDecl>{{"volren_debugView", "int", ""}, bindings::gradientScale},
                  .bind =
                      [](BindContext& c) {
                          bindings::bindGeometry(c);
                          bindings::bindLights(c);
                          bindings::bindGradientScale(c);
                          c.uniform("volren_debugView", c.settings.debugView);
                      },
                  .traits = {.calls = SlotList{"Gradient", "Reconstruction"}, .lights = LightUse::Optional}});
}

}  // namespace volren
