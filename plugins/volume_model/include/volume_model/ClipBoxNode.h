#pragma once
#include <volume_model/ClipNode.h>

namespace volren {

/// Keeps the inside of an axis-aligned box of its local coordinates (cropping).
class ClipBoxNode : public ClipNode
{
public:
    ClipBoxNode() = default;
    ClipBoxNode(const ClipBoxNode& other, const osg::CopyOp& copyop = osg::CopyOp::SHALLOW_COPY)
        : ClipNode(other, copyop), box(other.box) {}
    META_Node(volren, ClipBoxNode)

    /// The kept box.
    osg::BoundingBoxd box{-1, -1, -1, 1, 1, 1};

    bool leavesUnchanged(const std::array<osg::Vec3d, 8>& corners) const override;
    const char* clipKind() const override { return "box"; }
    osg::BoundingSphere computeBound() const override;

protected:
    bool inside(const osg::Vec3d& p) const override { return box.contains(p); }
};

}  // namespace volren
