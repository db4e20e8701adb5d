// MultiVolume: the per-member glue of a multi-volume set program (a pseudo-slot: the compositor
// adds it once per member, after the member's slots; ShaderCompositor, Composition::members).
#include <volume_renderer/ShaderFunctionRegistry.h>

namespace volren {

void registerMultiVolumeFunctions(ShaderFunctionRegistry& registry)
{
    // Each member's ray and sample over its own slots; bound once per member.
    registry.add({.slot = "MultiVolume",
                  .name = "member",
                  .uniforms = {{"volren_setToMember", "mat4", ""}},
                  .bind = [](BindContext& c) { c.uniform("volren_setToMember", osg::Matrixf(c.setToMember)); },
                  .traits = {.calls = SlotList{"Reconstruction", "Classification", "ClipPosition", "ClipRay", "Shading",
                                               "Acceleration", "Weighting"},
                             .multiVolume = true}});
}

}  // namespace volren
