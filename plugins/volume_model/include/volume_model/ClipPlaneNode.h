#pragma once
#include <volume_model/ClipNode.h>

#include <osg/Plane>

namespace volren {

/// Keeps the half-space a*x + b*y + c*z + d >= 0 of its local coordinates.
class ClipPlaneNode : public ClipNode
{
public:
    ClipPlaneNode() = default;
    ClipPlaneNode(const ClipPlaneNode& other, const osg::CopyOp& copyop = osg::CopyOp::SHALLOW_COPY)
        : ClipNode(other, copyop), plane(other.plane) {}
    META_Node(volren, ClipPlaneNode)

    /// The plane; its normal points into the kept half-space.
    osg::Plane plane{0.0, 0.0, 1.0, 0.0};

    bool leavesUnchanged(const std::array<osg::Vec3d, 8>& corners) const override;
    const char* clipKind() const override { return "plane"; }
    osg::BoundingSphere computeBound() const override { return osg::BoundingSphere(); }  ///< unbounded

protected:
    bool inside(const osg::Vec3d& p) const override { return plane.distance(p) >= 0.0; }
};

}  // namespace volren
