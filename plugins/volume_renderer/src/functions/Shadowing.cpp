// Shadowing implementations: the fraction of a light that reaches a sample.
#include <volume_renderer/ShaderFunctionRegistry.h>

namespace volren {

void registerShadowingFunctions(ShaderFunctionRegistry& registry)
{
    registry.add({.slot = "Shadowing", .name = "null", .traits = {.calls = SlotList{}}});
}

}  // namespace volren
