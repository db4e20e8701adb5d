// ClipRay implementations (template slot: one instance per clip plane, plus one for the depth
// of the opaque geometry when the scene has some).
#include "CommonBindings.h"

#include <volume_renderer/ShaderFunctionRegistry.h>

#include <volume_model/ClipPlaneNode.h>

namespace volren {

void registerClipRayFunctions(ShaderFunctionRegistry& registry)
{
    registry.add(ShaderFunction::plain("ClipRay", "null"));

    ShaderFunction plane;
    plane.slot = "ClipRay";
    plane.name = "plane";
    plane.file = "ClipRay/plane.glsl";
    plane.uniforms = {{"volren_clipRayPlane", "vec4", ""}};
    plane.bind = [](BindContext& c) {
        const auto* node = dynamic_cast<const ClipPlaneNode*>(c.clip().node);
        if (!node) return;
        // Keep where plane . (p * textureToShape) >= 0, i.e. (textureToShape * plane) . p >= 0.
        osg::Plane inTexture = node->plane;
        if (node->invert) inTexture.flip();
        inTexture.transformProvidingInverse(c.clip().textureToShape);
        const osg::Vec4d v = inTexture.asVec4();
        c.uniform("volren_clipRayPlane", osg::Vec4f(v));
    };
    registry.add(plane);

    // The depth texture and its viewport origin are per camera: the VolumeScene binds them
    // (AuxData::DepthTexture); the instance itself only needs the box geometry.
    ShaderFunction depth;
    depth.slot = "ClipRay";
    depth.name = "depth";
    depth.file = "ClipRay/depth.glsl";
    // (one per program, like the geometry and OSG's matrix: declared shared, never renamed).
    depth.uniforms = {{"osg_ModelViewProjectionMatrix", "mat4", "", true}, {"volren_viewportOrigin", "vec2", "", true}};
    for (UniformDecl u : bindings::geometry) {
        u.shared = true;
        depth.uniforms.push_back(u);
    }
    depth.textures = {{"volren_depthTexture", "sampler2D", true}};
    depth.needs = {AuxData::DepthTexture};
    depth.single = true;  // one depth buffer per camera
    depth.bind = [](BindContext& c) { c.unsuffixed(bindings::bindGeometry); };
    registry.add(depth);
}

}  // namespace volren
