// Shading implementations.
#include "CommonBindings.h"

#include <volume_renderer/ShaderFunctionRegistry.h>

#include <volume_model/RenderSettings.h>

namespace volren {

namespace {
using bindings::operator+;
}

void registerShadingFunctions(ShaderFunctionRegistry& registry)
{
    registry.add(ShaderFunction::plain("Shading", "null"));

    ShaderFunction lighting{"Shading", "lighting", "Shading/lighting.glsl", "", {"Shading/lights.glsl"},
                            bindings::geometry + bindings::lights, {}, {}, nullptr, false};
    lighting.bind = [](BindContext& c) {
        bindings::bindGeometry(c);
        bindings::bindLights(c);
    };
    registry.add(lighting);

    ShaderFunction threshold = lighting;
    threshold.name = "lighting_threshold";
    threshold.file = "Shading/lighting_threshold.glsl";
    threshold.uniforms.push_back({"volren_shadingThreshold", "float", ""});
    threshold.bind = [](BindContext& c) {
        bindings::bindGeometry(c);
        bindings::bindLights(c);
        c.uniform("volren_shadingThreshold", float(c.settings.shadingThreshold));
    };
    registry.add(threshold);

    ShaderFunction debug{"Shading", "debug", "Shading/debug.glsl", "", {},
                         bindings::geometry + bindings::lights +
                             std::vector<UniformDecl>{{"volren_debugView", "int", ""}, bindings::gradientScale},
                         {}, {}, nullptr, false};
    debug.bind = [](BindContext& c) {
        bindings::bindGeometry(c);
        bindings::bindLights(c);
        bindings::bindGradientScale(c);
        c.uniform("volren_debugView", c.settings.debugView);
    };
    registry.add(debug);
}

}  // namespace volren
