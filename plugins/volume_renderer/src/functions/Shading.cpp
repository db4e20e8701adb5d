// Shading implementations.
#include "CommonBindings.h"

#include <volume_renderer/ShaderFunctionRegistry.h>

#include <volume_model/RenderSettings.h>

#include <algorithm>

namespace volren {

namespace {

using bindings::operator+;

/// A shading lit by the scene's lights through the chosen Illumination (Shading/lights.glsl),
/// which the reference computes as `model`.
ShaderFunction lit(const std::string& name, const std::string& model, std::vector<UniformDecl> extra = {})
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
                       .lights = LightUse::Required},
            .reference = ReferenceModel::exact(model),
            .loops = [](const BindContext&) { return LoopCost{.perLight = 1.0}; }};  // the light loop
}

/// What the debug shading shows, in the order of its GLSL switch (volren_debugView).
const std::vector<std::string> debugViews = {"scalar", "position", "classification", "gradient", "normal", "view", "light"};

}  // namespace

void registerShadingFunctions(ShaderFunctionRegistry& registry)
{
    registry.add({.slot = "Shading",
                  .name = "null",
                  .traits = {.calls = SlotList{}},
                  .reference = ReferenceModel::exact("unlit")});
    // Every lit shading adds this fraction of the classified colour (bindings::bindLights).
    registry.addSlotParameter("Shading", {.key = "ambient", .defaultValue = 0.2, .lo = 0.0, .hi = 1.0,
                                          .help = "ambient light, as a fraction of the classified colour"});
    registry.add(lit("lighting", "lit"));

    ShaderFunction threshold = lit("lighting_threshold", "lit above threshold", {{"volren_shadingThreshold", "float", ""}});
    threshold.bind = [](BindContext& c) {
        bindings::bindGeometry(c);
        bindings::bindLights(c);
        c.uniform("volren_shadingThreshold", float(c.settings.number("shadingThreshold")));
    };
    threshold.parameters = {{.key = "shadingThreshold", .defaultValue = 0.05, .lo = 0.0, .hi = 1.0,
                             .help = "classified opacity below which samples are left unlit",
                             .label = "shading threshold"}};
    registry.add(threshold);

    // Lit on boundaries only, weighted by the gradient magnitude against volren_gradientScale.
    ShaderFunction surface = lit("lighting_surface", "lit on surfaces", {bindings::gradientScale});
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
                  .parameters = {{.key = "debugView", .type = ParameterType::Choice, .defaultValue = std::string("normal"),
                                  .choices = debugViews, .help = "what the debug shading shows",
                                  .label = "debug view", .panel = {PanelHint::Combo}}},
                  .bind =
                      [](BindContext& c) {
                          bindings::bindGeometry(c);
                          bindings::bindLights(c);
                          bindings::bindGradientScale(c);
                          const std::string view = c.settings.parameter<std::string>("debugView");
                          c.uniform("volren_debugView",
                                    int(std::find(debugViews.begin(), debugViews.end(), view) - debugViews.begin()));
                      },
                  .traits = {.calls = SlotList{"Gradient", "Reconstruction"}, .lights = LightUse::Optional},
                  .reference = ReferenceModel::none("its views show data (positions, gradients, normals), not light")});
}

}  // namespace volren
