// Gradient implementations (of the chosen GradientInput).
#include "CommonBindings.h"

#include <volume_renderer/ShaderFunctionRegistry.h>

namespace volren {

void registerGradientFunctions(ShaderFunctionRegistry& registry)
{
    // A zero gradient: lit samples' normals face the viewer (the reference models it).
    registry.add({.slot = "Gradient",
                  .name = "null",
                  .traits = {.calls = SlotList{}},
                  .reference = ReferenceModel::exact("no gradient")});
    for (const char* name : {"forward", "backward", "central", "central9"})
        registry.add({.slot = "Gradient",
                      .name = name,
                      .uniforms = bindings::geometry,
                      .bind = bindings::bindGeometry,
                      .traits = {.calls = SlotList{"GradientInput"},
                                 .required = {"GradientInput"},
                                 .aliases = name == std::string("central9") ? SlotList{"central-9"} : SlotList{}},
                      // One-sided and 9-point differences approximate the reference's central
                      // ones: lit colours differ where the normals do (on the composition sweep's
                      // lit shell, SweepHarness.cpp: one-sided 0.15, 9-point within its base).
                      .reference = name == std::string("central")    ? ReferenceModel::exact("central differences")
                                   : name == std::string("central9") ? ReferenceModel::approximate("central differences", 0.01)
                                                                     : ReferenceModel::approximate("central differences", 0.17),
                      // The cheapest and the widest against the default (central).
                      .benchRows = name == std::string("forward") || name == std::string("central9")
                                       ? std::vector<BenchRow>{{}}
                                       : std::vector<BenchRow>{},
                      // central9's 3x3 loops per lit sample (where the compiler keeps them loops).
                      .loops = name == std::string("central9")
                                   ? std::function<LoopCost(const BindContext&)>([](const BindContext&) {
                                         return LoopCost{.perSample = 12.0};
                                     })
                                   : std::function<LoopCost(const BindContext&)>()});
}

}  // namespace volren
