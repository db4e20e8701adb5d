#pragma once
// Internal to the pass: the geometry a volume (or a multi-volume set) is ray-cast through.
#include <volume_renderer/ShaderCompositor.h>

#include <osg/Geometry>
#include <osg/MatrixTransform>

#include <memory>
#include <string>
#include <vector>

namespace volren {

/// A box (back faces drawn, blended over what is behind) carrying one composed program and its
/// bound uniforms and textures. Its state is made from scratch when the composition changes.
struct VolumeProxy
{
    osg::ref_ptr<osg::MatrixTransform> transform = new osg::MatrixTransform;
    osg::ref_ptr<osg::Geometry> geometry;
    std::string key;                                 ///< composition key of the current state
    std::shared_ptr<const ComposedProgram> program;  ///< the program drawn
    osg::Vec3d boxSize;
    bool hidden = false;  ///< its occupancy grids show no sample can be visible: not drawn
    /// GPU builds of its auxiliary data for this frame, drawn before it under its state.
    std::vector<osg::ref_ptr<osg::Node>> prepasses;
    unsigned int lastCull = 0;

    /// Makes the box of `size` (centred on the transform) and the state of `program`, each only
    /// when it changed; returns the state set to bind into.
    osg::StateSet& update(const osg::Vec3d& size, std::shared_ptr<const ComposedProgram> program);
    /// Uses buffer objects and a vertex array object (core profiles) or client arrays.
    void useVertexArrayObject(bool core);
};

}  // namespace volren
