// Gradient implementations (of the chosen GradientInput).
#include "CommonBindings.h"

#include <volume_renderer/ShaderFunctionRegistry.h>

namespace volren {

void registerGradientFunctions(ShaderFunctionRegistry& registry)
{
    registry.add({.slot = "Gradient", .name = "null", .traits = {.calls = SlotList{}}});
    for (const char* name : {"forward", "backward", "central", "central9"})
        registry.add({.slot = "Gradient",
                      .name = name,
                      .uniforms = bindings::geometry,
                      .bind = bindings::bindGeometry,
                      .traits = {.calls = SlotList{"GradientInput"},
                                 .required = {"GradientInput"},
                                 .aliases = name == std::string("central9") ? SlotList{"central-9"} : SlotList{}},
                      // The cheapest and the widest against the default (central).
                      .benchRows = name == std::string("forward") || name == std::string("central9")
                                       ? std::vector<BenchRow>{{}}
                                       : std::vector<BenchRow>{}});
}

}  // namespace volren
