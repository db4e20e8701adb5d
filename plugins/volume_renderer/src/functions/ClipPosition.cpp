// ClipPosition implementations (template slot: one instance per clip shape).
#include <volume_renderer/ShaderFunctionRegistry.h>

#include <volume_model/ClipBoxNode.h>
#include <volume_model/ClipEllipsoidNode.h>
#include <volume_model/ClipMaskNode.h>
#include <volume_model/ClipPlaneNode.h>

namespace volren {

namespace {

const UniformDecl matrix = {"volren_clipMatrix", "mat4", ""};
const UniformDecl invert = {"volren_clipInvert", "bool", ""};

/// The traits of the implementation for clip shapes of `kind` (ClipNode::clipKind()).
ImplementationTraits clipping(const std::string& kind)
{
    return {.calls = SlotList{}, .clipKind = kind};
}

}  // namespace

void registerClipPositionFunctions(ShaderFunctionRegistry& registry)
{
    registry.add({.slot = "ClipPosition", .name = "null", .traits = {.calls = SlotList{}}, .reference = ReferenceModel::none("never an instance: a shape with no clip is an empty instance list")});

    ShaderFunction box{.slot = "ClipPosition",
                       .name = "box",
                       .uniforms = {matrix, invert, {"volren_clipBoxMin", "vec3", ""}, {"volren_clipBoxMax", "vec3", ""}},
                       .traits = clipping("box"),
                       .reference = ReferenceModel::exact("clip shape")};
    box.bind = [](BindContext& c) {
        const auto* node = dynamic_cast<const ClipBoxNode*>(c.clip().node);
        if (!node) return;
        c.uniform("volren_clipMatrix", osg::Matrixf(c.clip().textureToShape));
        c.uniform("volren_clipInvert", node->invert);
        c.uniform("volren_clipBoxMin", osg::Vec3f(node->box._min));
        c.uniform("volren_clipBoxMax", osg::Vec3f(node->box._max));
    };
    registry.add(box);

    ShaderFunction ellipsoid{
        .slot = "ClipPosition",
        .name = "ellipsoid",
        .uniforms = {matrix, invert, {"volren_clipCentre", "vec3", ""}, {"volren_clipRadii", "vec3", ""}},
        .traits = clipping("ellipsoid"),
        .reference = ReferenceModel::exact("clip shape")};
    ellipsoid.bind = [](BindContext& c) {
        const auto* node = dynamic_cast<const ClipEllipsoidNode*>(c.clip().node);
        if (!node) return;
        c.uniform("volren_clipMatrix", osg::Matrixf(c.clip().textureToShape));
        c.uniform("volren_clipInvert", node->invert);
        c.uniform("volren_clipCentre", osg::Vec3f(node->center));
        c.uniform("volren_clipRadii", osg::Vec3f(node->radii));
    };
    registry.add(ellipsoid);

    ShaderFunction plane{.slot = "ClipPosition",
                         .name = "plane",
                         .uniforms = {invert, {"volren_clipPlane", "vec4", ""}},
                         .traits = clipping("plane"),
                         .reference = ReferenceModel::exact("clip shape")};
    plane.bind = [](BindContext& c) {
        const auto* node = dynamic_cast<const ClipPlaneNode*>(c.clip().node);
        if (!node) return;
        osg::Plane inTexture = node->plane;
        inTexture.transformProvidingInverse(c.clip().textureToShape);
        c.uniform("volren_clipPlane", osg::Vec4f(inTexture.asVec4()));
        c.uniform("volren_clipInvert", node->invert);
    };
    registry.add(plane);

    ShaderFunction mask{
        .slot = "ClipPosition",
        .name = "mask",
        .uniforms = {matrix, invert, {"volren_clipThreshold", "float", ""}, {"volren_clipMaskValue", "vec2", ""}},
        .textures = {{"volren_clipMask", "sampler3D"}},
        .traits = clipping("mask"),
        .reference = ReferenceModel::exact("clip shape")};
    mask.bind = [](BindContext& c) {
        const auto* node = dynamic_cast<const ClipMaskNode*>(c.clip().node);
        if (!node || !node->mask) return;
        // texture space -> mask-local -> mask texture space ([0,1] across the mask's box).
        const osg::Vec3d size = node->mask->worldSize();
        const osg::Matrixd toMaskTexture = osg::Matrixd::scale(1.0 / size.x(), 1.0 / size.y(), 1.0 / size.z()) *
                                           osg::Matrixd::translate(0.5, 0.5, 0.5);
        c.uniform("volren_clipMatrix", osg::Matrixf(c.clip().textureToShape * toMaskTexture));
        c.uniform("volren_clipInvert", node->invert);
        c.uniform("volren_clipThreshold", float(node->threshold));
        const double norm = normalisedScale(node->mask->type());
        c.uniform("volren_clipMaskValue", osg::Vec2f(float(norm * node->mask->rescaleSlope()),
                                                     float(node->mask->rescaleIntercept())));
        c.texture("volren_clipMask", c.volumeTexture(*node->mask, true));
    };
    registry.add(mask);
}

}  // namespace volren
