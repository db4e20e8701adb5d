// Shading implementations.
#include <volume_renderer/ShaderFunctionRegistry.h>

namespace volren {

void registerShadingFunctions(ShaderFunctionRegistry& registry)
{
    registry.add({"Shading", "null", "Shading/null.glsl", "", {}, {}, {}, nullptr});
}

}  // namespace volren
