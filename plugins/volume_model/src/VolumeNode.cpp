#include <volume_model/VolumeNode.h>

namespace volren {

VolumeNode::VolumeNode() = default;

VolumeNode::VolumeNode(const VolumeNode& other, const osg::CopyOp& copyop)
    : osg::Node(other, copyop),
      settings(other.settings),
      _volume(other._volume),
      _transferFunction(other._transferFunction)
{
}

void VolumeNode::setVolume(Volume* volume)
{
    _volume = volume;
    dirtyBound();
}

osg::BoundingBox VolumeNode::localBox() const
{
    osg::BoundingBox box;
    if (!_volume || _volume->voxelCount() == 0) return box;
    const osg::Vec3d half = _volume->worldSize() * 0.5;
    box.expandBy(-half);
    box.expandBy(half);
    return box;
}

osg::BoundingSphere VolumeNode::computeBound() const
{
    const osg::BoundingBox box = localBox();
    if (!box.valid()) return osg::BoundingSphere();
    return osg::BoundingSphere(box);
}

}  // namespace volren
