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
        auto ahead = _prefetched.find({c, t});
        if (ahead != _prefetched.end() && ahead->second.from.get() == _volume.get() &&
            ahead->second.modified == _volume->modifiedCount()) {
            node.setVolume(ahead->second.block.get());
            ++_prefetchHits;
        } else {
            node.setVolume(channelOf(*_volume, c, t).get());
            ++_blockCopies;
        }
        if (ahead != _prefetched.end()) _prefetched.erase(ahead);
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
            if (!block.scaled) block.scaled = new TransferFunction;  // one object: renderers update its table
            block.scaled->assign(*scaledOpacity(*tf, scale));
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

std::vector<int> VolumeNode::drawnChannels() const
{
    if (!showsChannels()) return {0};
    std::vector<int> shown;
    for (int c = 0; c < _volume->channels() && std::size_t(c) < channels.size(); ++c)
        if (channels[std::size_t(c)].visible) shown.push_back(c);
    return shown;
}

std::size_t VolumeNode::prefetch(int t, const std::vector<int>& channels)
{
    osg::ref_ptr<const Volume> volume;
    unsigned int modified = 0;
    std::vector<int> needed;
    {
        std::lock_guard<std::mutex> lock(_blockMutex);
        if (!_volume || _volume->fullResolution() || t < 0 || t >= _volume->frames()) return 0;
        volume = _volume;
        modified = _volume->modifiedCount();
        for (int c : channels) {
            if (c < 0 || c >= _volume->channels()) continue;
            auto it = _prefetched.find({c, t});
            const bool shown = std::size_t(c) < _blockNodes.size() && _blockNodes[std::size_t(c)].timePoint == t &&
                               _blockNodes[std::size_t(c)].volume.get() == volume.get() &&
                               _blockNodes[std::size_t(c)].modified == modified;
            if (!shown && (it == _prefetched.end() || it->second.from.get() != volume.get() || it->second.modified != modified))
                needed.push_back(c);
        }
    }
    std::size_t bytes = 0;
    for (int c : needed) {
        osg::ref_ptr<Volume> block = channelOf(*volume, c, t);  // outside the lock: the cull goes on
        bytes += block->byteSize();
        std::lock_guard<std::mutex> lock(_blockMutex);
        _prefetched[{c, t}] = {block, volume, modified};
    }
    return bytes;
}

void VolumeNode::dropPrefetched(const std::function<bool(int c, int t)>& keep)
{
    std::lock_guard<std::mutex> lock(_blockMutex);
    for (auto it = _prefetched.begin(); it != _prefetched.end();)
        it = keep(it->first.first, it->first.second) ? std::next(it) : _prefetched.erase(it);
}

std::size_t VolumeNode::prefetchedBytes() const
{
    std::lock_guard<std::mutex> lock(_blockMutex);
    std::size_t bytes = 0;
    for (const auto& entry : _prefetched) bytes += entry.second.block->byteSize();
    return bytes;
}

std::vector<VolumeNode*> VolumeNode::drawnNodes()
{
    if (!drawsBlocks()) return {this};
    std::vector<VolumeNode*> nodes;
    for (int c : drawnChannels()) nodes.push_back(channelNode(c));
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
