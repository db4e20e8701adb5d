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
    box.vertexFile = "RaySetup/box.vert";
    box.includes = {"RaySetup/ray.glsl"};
    box.uniforms = {{"volren_writesDepth", "bool", ""}};
    box.bind = [](BindContext& c) {
        bindings::bindGeometry(c);  // the vertex stage reads volren_worldSize
        c.uniform("volren_writesDepth", c.writesDepth);
    };
    registry.add(box);

    ShaderFunction hybrid = box;
    hybrid.name = "hybrid";
    hybrid.file = "RaySetup/hybrid.glsl";
    registry.add(hybrid);

    // Entry points come from a front-face pass the VolumeScene draws into a per-camera image
    // (AuxData::EntryPoints), which also sets volren_viewportOrigin and volren_frameStamp.
    ShaderFunction rasterised = box;
    rasterised.name = "rasterised";
    rasterised.file = "RaySetup/rasterised.glsl";
    rasterised.uniforms.push_back({"volren_viewportOrigin", "vec2", ""});
    rasterised.uniforms.push_back({"volren_frameStamp", "float", ""});
    rasterised.needs = {AuxData::EntryPoints};
    registry.add(rasterised);

    ShaderFunction none = box;
    none.name = "null";
    none.file = "RaySetup/null.glsl";
    none.includes.clear();
    none.uniforms.clear();
    registry.add(none);
}

}  // namespace volren
