// RaySetup implementations: they own main() and the proxy geometry's vertex stage.
#include "CommonBindings.h"

#include <volume_renderer/ShaderFunctionRegistry.h>

namespace volren {

void registerRaySetupFunctions(ShaderFunctionRegistry& registry)
{
    ShaderFunction box;
    box.slot = "RaySetup";
    box.name = "box_intersection";
    box.file = "RaySetup/box_intersection.glsl";
    box.vertexFile = "RaySetup/box_intersection.vert";
    box.uniforms = {{"volren_writesDepth", "bool", ""}};
    box.bind = [](BindContext& c) {
        bindings::bindGeometry(c);  // the vertex stage reads volren_worldSize
        c.uniform("volren_writesDepth", c.writesDepth);
    };
    registry.add(box);

    ShaderFunction none = box;
    none.name = "null";
    none.file = "RaySetup/null.glsl";
    none.uniforms.clear();
    registry.add(none);
}

}  // namespace volren
