// ClipRay implementations (template slot: one instance per clip plane, plus one for the depth
// of the opaque geometry when the scene has some).
#include "CommonBindings.h"

#include <volume_renderer/ScreenPasses.h>
#include <volume_renderer/ShaderCompositor.h>
#include <volume_renderer/ShaderFunctionRegistry.h>

#include <volume_model/ClipPlaneNode.h>

namespace volren {

void registerClipRayFunctions(ShaderFunctionRegistry& registry)
{
    registry.add({.slot = "ClipRay", .name = "null", .traits = {.calls = SlotList{}}, .reference = ReferenceModel::none("never an instance: a shape with no clip is an empty instance list")});

    registry.add({.slot = "ClipRay",
                  .name = "plane",
                  .uniforms = {{"volren_clipRayPlane", "vec4", ""}},
                  .bind =
                      [](BindContext& c) {
                          const auto* node = dynamic_cast<const ClipPlaneNode*>(c.clip().node);
                          if (!node) return;
                          // Keep where plane . (p * textureToShape) >= 0, i.e. (textureToShape * plane) . p >= 0.
                          osg::Plane inTexture = node->plane;
                          if (node->invert) inTexture.flip();
                          inTexture.transformProvidingInverse(c.clip().textureToShape);
                          c.uniform("volren_clipRayPlane", osg::Vec4f(inTexture.asVec4()));
                      },
                  .traits = {.calls = SlotList{}, .clipKind = "plane"},
                  .reference = ReferenceModel::exact("clip shape")});

    // The depth of the opaque geometry drawn before the volumes, per camera (ScreenPasses): as
    // sampler2D volren_depthTexture read with texelFetch at gl_FragCoord.xy - volren_viewportOrigin,
    // which the screen pass sets too.
    registry.addAuxKind({.name = "depth texture",
                         .scope = AuxScope::Camera,
                         .perCamera = [](AuxCameraRequest& r) {
                             return r.screen.depthState(r.cv, r.program.textureUnits.at("volren_depthTexture"));
                         }});
    // The instance itself only needs the box geometry (one per program, like OSG's matrix:
    // declared shared, never renamed).
    ShaderFunction depth{.slot = "ClipRay",
                         .name = "depth",
                         .uniforms = {{"osg_ModelViewProjectionMatrix", "mat4", "", true},
                                      {"volren_viewportOrigin", "vec2", "", true}},
                         .textures = {{"volren_depthTexture", "sampler2D", true}},
                         .needs = {"depth texture"},
                         .bind = [](BindContext& c) { c.unsuffixed(bindings::bindGeometry); },
                         .traits = {.calls = SlotList{}, .clipKind = "depth", .single = true},
                         .reference = ReferenceModel::exact("opaque geometry's depth")};
    for (UniformDecl u : bindings::geometry) {
        u.shared = true;
        depth.uniforms.push_back(u);
    }
    registry.add(depth);
}

}  // namespace volren
