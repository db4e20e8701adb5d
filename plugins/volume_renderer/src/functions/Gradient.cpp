// Gradient and GradientInput implementations.
#include "CommonBindings.h"

#include <volume_renderer/ShaderFunctionRegistry.h>

namespace volren {

void registerGradientFunctions(ShaderFunctionRegistry& registry)
{
    registry.add(ShaderFunction::plain("Gradient", "null"));
    for (const char* name : {"forward", "backward", "central", "central9"})
        registry.add({"Gradient", name, std::string("Gradient/") + name + ".glsl", "", {}, bindings::geometry, {}, {},
                      [](BindContext& c) { bindings::bindGeometry(c); }, false});

    for (const char* name : {"null", "scalar", "alpha"})
        registry.add({"GradientInput", name, std::string("GradientInput/") + name + ".glsl", "", {}, {}, {}, {},
                      nullptr, false});
}

}  // namespace volren
