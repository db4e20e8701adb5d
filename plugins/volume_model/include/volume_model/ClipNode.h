#pragma once
#include <osg/BoundingBox>
#include <osg/Node>
#include <osg/NodeVisitor>

#include <array>

namespace volren {

/// A clip shape in the scene: it keeps part of every volume it overlaps (the inside of a box,
/// ellipsoid or mask; the positive side of a plane) and removes the rest; `invert` keeps the
/// complement instead. Several shapes combine: a sample survives only if every shape keeps it.
/// Shapes live in their own local coordinates; transforms above them place them.
class ClipNode : public osg::Node
{
public:
    /// Keep the complement of the shape instead of the shape.
    bool invert = false;

    /// Whether the point `p` (local coordinates) is kept; the CPU definition of the shape.
    bool keeps(const osg::Vec3d& p) const { return inside(p) != invert; }
    /// Whether the shape leaves every point of the box with corners `corners` (local
    /// coordinates) unchanged; conservative (false when unsure).
    virtual bool leavesUnchanged(const std::array<osg::Vec3d, 8>& corners) const = 0;
    /// The kind of shape ("plane", "box", "ellipsoid", "mask"): the renderer clips it with the
    /// implementation that declares this kind.
    virtual const char* clipKind() const = 0;

protected:
    ClipNode() = default;
    ClipNode(const ClipNode& other, const osg::CopyOp& copyop) : osg::Node(other, copyop), invert(other.invert) {}
    /// Whether `p` lies in the shape itself (before `invert`).
    virtual bool inside(const osg::Vec3d& p) const = 0;
};

}  // namespace volren
