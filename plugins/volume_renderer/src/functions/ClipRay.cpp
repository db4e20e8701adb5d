// ClipRay implementations.
#include <volume_renderer/ShaderFunctionRegistry.h>

namespace volren {

void registerClipRayFunctions(ShaderFunctionRegistry& registry)
{
    registry.add({"ClipRay", "null", "ClipRay/null.glsl", "", {}, {}, {}, nullptr});
}

}  // namespace volren
