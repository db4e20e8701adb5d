#pragma once
#include <volume_model/RenderSettings.h>
#include <volume_model/TransferFunction.h>
#include <volume_model/Volume.h>

#include <osg/BoundingBox>
#include <osg/Node>
#include <osg/NodeVisitor>

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

    /// Box of the volume in the node's local coordinates (invalid without a volume).
    osg::BoundingBox localBox() const;
    /// Bounding sphere of localBox().
    osg::BoundingSphere computeBound() const override;

protected:
    ~VolumeNode() override = default;

private:
    osg::ref_ptr<Volume> _volume;
    osg::ref_ptr<TransferFunction> _transferFunction;
};

}  // namespace volren
