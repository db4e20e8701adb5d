// Jitter implementations.
#include <volume_renderer/ShaderFunctionRegistry.h>

namespace volren {

void registerJitterFunctions(ShaderFunctionRegistry& registry)
{
    registry.add({"Jitter", "null", "Jitter/null.glsl", "", {}, {}, {}, nullptr});
    registry.add({"Jitter", "hash", "Jitter/hash.glsl", "", {}, {}, {}, nullptr});
}

}  // namespace volren
