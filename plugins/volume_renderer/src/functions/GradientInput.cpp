// GradientInput implementations: the field a Gradient differentiates.
#include <volume_renderer/ShaderFunctionRegistry.h>

namespace volren {

void registerGradientInputFunctions(ShaderFunctionRegistry& registry)
{
    registry.add({.slot = "GradientInput", .name = "null", .traits = {.calls = SlotList{}}});
    registry.add({.slot = "GradientInput", .name = "scalar", .traits = {.calls = SlotList{"Reconstruction"}}});
    registry.add({.slot = "GradientInput",
                  .name = "alpha",
                  .traits = {.calls = SlotList{"Reconstruction", "Classification"}}});
}

}  // namespace volren
