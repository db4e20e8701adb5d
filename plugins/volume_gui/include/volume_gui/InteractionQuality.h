#pragma once
#include <volume_model/VolumeNode.h>

#include <osgGA/GUIEventHandler>

namespace volren {

/// The interaction-quality policy of `volren view`: while the camera moves or a TF point is
/// dragged (a mouse button pressed or dragged, or the wheel turned), the node is sampled one
/// level of detail coarser (its `lod` raised by one: the next mip level, with a step twice as
/// long); `idleSeconds` after the last such event the full level returns with the next frame
/// (unless the level was changed meanwhile, e.g. in the settings panel: that change stays).
class InteractionQuality : public osgGA::GUIEventHandler
{
public:
    explicit InteractionQuality(VolumeNode* node, double idleSeconds = 0.3) : _node(node), _idle(idleSeconds) {}
    bool handle(const osgGA::GUIEventAdapter& ea, osgGA::GUIActionAdapter& aa) override;
    bool lowered() const { return _lowered; }  ///< whether the coarser level is in use

private:
    osg::ref_ptr<VolumeNode> _node;
    double _idle;
    bool _lowered = false;
    int _full = 0, _reduced = 1;
    double _last = 0.0;
};

}  // namespace volren
