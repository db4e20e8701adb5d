#pragma once
#include <volume_model/ClipNode.h>

namespace volren {

/// Keeps the inside of an axis-aligned ellipsoid of its local coordinates.
class ClipEllipsoidNode : public ClipNode
{
public:
    ClipEllipsoidNode() = default;
    ClipEllipsoidNode(const ClipEllipsoidNode& other, const osg::CopyOp& copyop = osg::CopyOp::SHALLOW_COPY)
        : ClipNode(other, copyop), center(other.center), radii(other.radii) {}
    META_Node(volren, ClipEllipsoidNode)

    osg::Vec3d center{0, 0, 0};  ///< centre
    osg::Vec3d radii{1, 1, 1};   ///< semi-axes along x, y, z (positive)

    bool leavesUnchanged(const std::array<osg::Vec3d, 8>& corners) const override;
    const char* clipKind() const override { return "ellipsoid"; }
    osg::BoundingSphere computeBound() const override;

protected:
    bool inside(const osg::Vec3d& p) const override;
};

}  // namespace volren
