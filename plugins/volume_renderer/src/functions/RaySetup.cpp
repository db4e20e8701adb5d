// RaySetup implementations: they own main() and the proxy geometry's vertex stage.
#include <volume_renderer/ShaderFunctionRegistry.h>

#include <volume_model/Volume.h>

namespace volren {

void registerRaySetupFunctions(ShaderFunctionRegistry& registry)
{
    ShaderFunction box;
    box.slot = "RaySetup";
    box.name = "box_intersection";
    box.file = "RaySetup/box_intersection.glsl";
    box.vertexFile = "RaySetup/box_intersection.vert";
    box.bind = [](BindContext& c) { c.uniform("volren_worldSize", osg::Vec3f(c.volume.worldSize())); };
    registry.add(box);
}

}  // namespace volren
