// RaySetup implementations: they own main() and the proxy geometry's vertex stage.
#include "CommonBindings.h"

#include <volume_renderer/ScreenPasses.h>
#include <volume_renderer/ShaderFunctionRegistry.h>

namespace volren {

namespace {

/// What every ray setup shares: the box's vertex stage, the common ray tail, the geometry.
ShaderFunction raySetup(const std::string& name)
{
    return {.slot = "RaySetup",
            .name = name,
            .vertexFile = "RaySetup/box.vert",
            .includes = {"RaySetup/ray.glsl"},
            .uniforms = {{"volren_writesDepth", "bool", ""}},
            .bind =
                [](BindContext& c) {
                    bindings::bindGeometry(c);  // the vertex stage reads volren_worldSize
                    c.uniform("volren_writesDepth", c.writesDepth);
                },
            .traits = {.calls = SlotList{"ClipRay", "Jitter", "RayTraversal"}},
            .reference = ReferenceModel::exact("the volume box from the near plane")};
}

}  // namespace

void registerRaySetupFunctions(ShaderFunctionRegistry& registry)
{
    registry.add(raySetup("box_intersection"));
    registry.add(raySetup("hybrid"));

    // Entry points come from a front-face pass drawn per camera (ScreenPasses): the volume-space
    // points of the box's rasterised front faces as image2D volren_entryPoints (rgba32f: xyz,
    // w = volren_frameStamp of the frame that wrote it); it also sets volren_viewportOrigin and
    // volren_frameStamp.
    registry.addAuxKind({.name = "entry points",
                         .scope = AuxScope::Camera,
                         .perCamera = [](AuxCameraRequest& r) {
                             return r.screen.entryState(r.cv, r.node, r.box, r.boxSize, r.matrix);
                         }});
    ShaderFunction rasterised = raySetup("rasterised");
    rasterised.uniforms.push_back({"volren_viewportOrigin", "vec2", ""});
    rasterised.uniforms.push_back({"volren_frameStamp", "float", ""});
    rasterised.needs = {"entry points"};
    registry.add(rasterised);

    registry.add({.slot = "RaySetup",
                  .name = "null",
                  .vertexFile = "RaySetup/box.vert",
                  .bind = raySetup("null").bind,
                  .traits = {.calls = SlotList{}},
                  .reference = ReferenceModel::none("it casts no ray: the sweep's 'drawn' check is its test")});
}

}  // namespace volren
