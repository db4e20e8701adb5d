// ClipRay implementations (template slot: one instance per clip plane).
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
}

}  // namespace volren
