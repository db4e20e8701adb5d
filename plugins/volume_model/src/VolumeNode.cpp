#include <volume_model/VolumeNode.h>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace volren {

VolumeNode::VolumeNode() = default;

VolumeNode::VolumeNode(const VolumeNode& other, const osg::CopyOp& copyop)
    : osg::Node(other, copyop),
      settings(other.settings),
      channels(other.channels),
      _volume(other._volume),
      _transferFunction(other._transferFunction),
      _timePoint(other._timePoint)
{
}

void VolumeNode::setVolume(Volume* volume)
{
    _volume = volume;
    dirtyBound();
}

void VolumeNode::setTimePoint(int t)
{
    if (t < 0) throw std::out_of_range("volume '" + getName() + "': time point " + std::to_string(t) + " (counted from 0)");
    _timePoint = t;
}

int VolumeNode::shownTimePoint() const
{
    return _volume ? std::min(_timePoint, _volume->frames() - 1) : 0;
}

void VolumeNode::showChannels(const std::vector<int>& shown)
{
    const int count = _volume ? _volume->channels() : 0;
    for (int c : shown)
        if (c < 0 || c >= count)
            throw std::out_of_range("volume '" + getName() + "' has no channel " + std::to_string(c) + " (it has " +
                                    std::to_string(count) + ", counted from 0)");
    if (channels.size() < std::size_t(count)) channels.resize(std::size_t(count));
    for (std::size_t c = 0; c < channels.size(); ++c)
        channels[c].visible = std::find(shown.begin(), shown.end(), int(c)) != shown.end();
}

bool VolumeNode::showsChannels() const
{
    return channels.size() > 1 && _volume && _volume->channels() > 1;
}

bool VolumeNode::drawsBlocks() const
{
    return _volume && !_volume->fullResolution() && (showsChannels() || shownTimePoint() > 0);
}

VolumeNode* VolumeNode::channelNode(int c) const
{
    std::lock_guard<std::mutex> lock(_blockMutex);
    if (_blockNodes.size() <= std::size_t(c)) _blockNodes.resize(std::size_t(c) + 1);
    BlockNode& block = _blockNodes[std::size_t(c)];
    if (!block.node) block.node = new VolumeNode;
    VolumeNode& node = *block.node;
    const int t = shownTimePoint();
    if (block.volume.get() != _volume.get() || block.modified != _volume->modifiedCount() || block.timePoint != t) {
        node.setVolume(channelOf(*_volume, c, t).get());
        ++_blockCopies;
        block.volume = _volume.get();
        block.modified = _volume->modifiedCount();
        block.timePoint = t;
    }
    const std::string name = getName() + " [channel " + std::to_string(c) + "]";
    if (node.getName() != name) node.setName(name);
    TransferFunction* tf = std::size_t(c) < channels.size() && channels[std::size_t(c)].transferFunction
                               ? channels[std::size_t(c)].transferFunction.get()
                               : _transferFunction.get();
    if (const double scale = std::size_t(c) < channels.size() ? channels[std::size_t(c)].opacity : 1.0; tf && scale != 1.0) {
        if (block.from.get() != tf || block.fromModified != tf->modifiedCount() || block.scale != scale || !block.scaled) {
            block.scaled = scaledOpacity(*tf, scale);
            block.from = tf;
            block.fromModified = tf->modifiedCount();
            block.scale = scale;
        }
        tf = block.scaled.get();
    }
    if (node.getTransferFunction() != tf) node.setTransferFunction(tf);
    if (!(node.settings == settings)) node.settings = settings;  // written only when changed (others may read it)
    if (node.getNodeMask() != getNodeMask()) node.setNodeMask(getNodeMask());
    return &node;
}

std::vector<VolumeNode*> VolumeNode::drawnNodes()
{
    if (!drawsBlocks()) return {this};
    if (!showsChannels()) return {channelNode(0)};
    std::vector<VolumeNode*> nodes;
    for (int c = 0; c < _volume->channels() && std::size_t(c) < channels.size(); ++c)
        if (channels[std::size_t(c)].visible) nodes.push_back(channelNode(c));
    return nodes;
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
