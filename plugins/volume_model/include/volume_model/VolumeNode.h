#pragma once
#include <volume_model/ChannelDisplay.h>
#include <volume_model/RenderSettings.h>
#include <volume_model/TransferFunction.h>
#include <volume_model/Volume.h>

#include <osg/BoundingBox>
#include <osg/Node>
#include <osg/NodeVisitor>

#include <functional>
#include <map>
#include <mutex>
#include <vector>

namespace volren {

/// A volume in the scene graph: a shared Volume and TransferFunction plus per-node settings.
/// The box spans dims*spacing centred on the node's origin; transforms above it place it.
/// It draws nothing by itself: a VolumeScene above it renders it.
class VolumeNode : public osg::Node
{
public:
    VolumeNode();
    VolumeNode(const VolumeNode& other, const osg::CopyOp& copyop = osg::CopyOp::SHALLOW_COPY);
    META_Node(volren, VolumeNode)

    /// Sets the shown volume (may be shared with other nodes) and updates the bound.
    void setVolume(Volume* volume);
    Volume* getVolume() { return _volume.get(); }              ///< shown volume
    const Volume* getVolume() const { return _volume.get(); }  ///< shown volume

    /// Sets the transfer function (may be shared with other nodes).
    void setTransferFunction(TransferFunction* tf) { _transferFunction = tf; }
    TransferFunction* getTransferFunction() { return _transferFunction.get(); }              ///< classification
    const TransferFunction* getTransferFunction() const { return _transferFunction.get(); }  ///< classification

    /// Per-node render settings; read by the renderer every frame.
    RenderSettings settings;

    /// How each channel of the volume is shown (index = channel). With at most one entry, or a
    /// single-channel volume, the node shows channel 0 through its own transfer function (what
    /// older scenes say); with more, every visible channel is drawn, all in one ray.
    std::vector<ChannelDisplay> channels;
    /// Shows time point `t` (from 0) of a time-series volume; a volume with fewer time points
    /// shows its last. Throws std::out_of_range for a negative `t`.
    void setTimePoint(int t);
    int timePoint() const { return _timePoint; }  ///< the time point asked for (see setTimePoint)
    /// The time point drawn: timePoint() within the volume's time points (0 without a volume).
    int shownTimePoint() const;

    /// Shows exactly the channels `shown` (from 0) and hides the others; a node with no channel
    /// displays gets one per channel, through its own transfer function. Throws
    /// std::out_of_range naming the node when a channel does not exist.
    void showChannels(const std::vector<int>& shown);
    /// Whether it shows several channels (see `channels`).
    bool showsChannels() const;
    /// Whether it is drawn as nodes of its volume's blocks (channelNode) rather than itself: when
    /// it shows several channels or a time point after the first. Never for a volume opened
    /// lazily, whose source holds one channel and time point.
    bool drawsBlocks() const;
    /// The node that draws channel `c` at shownTimePoint() when drawsBlocks(): that block of the
    /// volume (copied once per change of the volume or the time point: only the shown blocks
    /// reach the GPU), the channel's transfer function (the node's where it names none; a copy
    /// with its opacity scaled, scaledOpacity(), where the channel's opacity is not 1), this
    /// node's settings and mask, named "<name> [channel c]". The same object for the same node
    /// and channel, so that a renderer keeps its programs.
    VolumeNode* channelNode(int c) const;
    /// Blocks channelNode() has copied out so far: each is one volume texture a renderer uploads
    /// (stepping a time series copies the shown channels of the new time point, nothing else).
    /// Blocks taken from prefetch() are not copies of channelNode()'s (see prefetchHits()).
    std::size_t blockCopies() const { return _blockCopies; }
    /// The channels drawnNodes() draws: the visible ones, or channel 0 when it shows one.
    std::vector<int> drawnChannels() const;
    /// Copies ahead of time the blocks of `channels` at time point `t` (drawnChannels(), read on
    /// the thread that edits the node), so that channelNode() takes them instead of copying when
    /// the node steps to `t`; safe while another thread draws the node, as long as the volume
    /// is not reallocated meanwhile. Returns the bytes it copied.
    std::size_t prefetch(int t, const std::vector<int>& channels);
    /// Drops the prefetched blocks (channel c, time point t) for which `keep(c, t)` is false.
    void dropPrefetched(const std::function<bool(int c, int t)>& keep);
    /// Bytes of the prefetched blocks held now.
    std::size_t prefetchedBytes() const;
    /// Blocks channelNode() took from prefetch() instead of copying them.
    std::size_t prefetchHits() const { return _prefetchHits; }
    /// The nodes a renderer draws for this one: itself, or channelNode(c) for each visible
    /// channel (channel 0 when it shows one channel).
    std::vector<VolumeNode*> drawnNodes();

    /// Box of the volume in the node's local coordinates (invalid without a volume).
    osg::BoundingBox localBox() const;
    /// Bounding sphere of localBox().
    osg::BoundingSphere computeBound() const override;

protected:
    ~VolumeNode() override = default;

private:
    osg::ref_ptr<Volume> _volume;
    osg::ref_ptr<TransferFunction> _transferFunction;
    int _timePoint = 0;
    /// A channelNode() and the block (volume, its modified count, time point) its voxels are.
    struct BlockNode
    {
        osg::ref_ptr<VolumeNode> node;
        osg::ref_ptr<const Volume> volume;  ///< held: a new volume never takes its address
        unsigned int modified = 0;
        int timePoint = -1;
        /// The opacity-scaled copy of a transfer function (`from` at its `fromModified`, times `scale`).
        osg::ref_ptr<TransferFunction> scaled;
        osg::ref_ptr<const TransferFunction> from;
        unsigned int fromModified = 0;
        double scale = 1.0;
    };
    mutable std::vector<BlockNode> _blockNodes;  ///< per channel
    mutable std::size_t _blockCopies = 0;
    /// Blocks copied ahead (prefetch), by (channel, time point), with the volume and its
    /// modified count they were copied from.
    struct Prefetched
    {
        osg::ref_ptr<Volume> block;
        osg::ref_ptr<const Volume> from;
        unsigned int modified = 0;
    };
    mutable std::map<std::pair<int, int>, Prefetched> _prefetched;
    mutable std::size_t _prefetchHits = 0;
    mutable std::mutex _blockMutex;
};

}  // namespace volren
