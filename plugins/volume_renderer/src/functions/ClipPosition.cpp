// ClipPosition implementations.
#include <volume_renderer/ShaderFunctionRegistry.h>

namespace volren {

void registerClipPositionFunctions(ShaderFunctionRegistry& registry)
{
    registry.add({"ClipPosition", "null", "ClipPosition/null.glsl", "", {}, {}, {}, nullptr});
}

}  // namespace volren
