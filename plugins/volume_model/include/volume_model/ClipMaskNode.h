#pragma once
#include <volume_model/ClipNode.h>
#include <volume_model/Volume.h>

namespace volren {

/// Keeps where a mask volume (placed like a VolumeNode: dims * spacing centred on the origin)
/// reaches `threshold` (data units); outside the mask's box nothing is kept.
class ClipMaskNode : public ClipNode
{
public:
    ClipMaskNode() = default;
    ClipMaskNode(const ClipMaskNode& other, const osg::CopyOp& copyop = osg::CopyOp::SHALLOW_COPY)
        : ClipNode(other, copyop), mask(other.mask), threshold(other.threshold) {}
    META_Node(volren, ClipMaskNode)

    osg::ref_ptr<Volume> mask;  ///< the mask voxels
    double threshold = 0.5;     ///< data value at and above which the mask keeps

    bool leavesUnchanged(const std::array<osg::Vec3d, 8>&) const override { return false; }
    const char* clipKind() const override { return "mask"; }
    osg::BoundingSphere computeBound() const override;

protected:
    bool inside(const osg::Vec3d& p) const override;  ///< nearest-voxel lookup
};

}  // namespace volren
