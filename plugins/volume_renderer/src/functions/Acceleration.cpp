// Acceleration implementations: where along the ray sampling is worth it (empty-space skipping).
#include <volume_renderer/ShaderFunctionRegistry.h>

namespace volren {

void registerAccelerationFunctions(ShaderFunctionRegistry& registry)
{
    registry.add({.slot = "Acceleration", .name = "null", .traits = {.calls = SlotList{}}});
}

}  // namespace volren
