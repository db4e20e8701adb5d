#include <volume_gui/InteractionQuality.h>

#include <algorithm>

namespace volren {

bool InteractionQuality::handle(const osgGA::GUIEventAdapter& ea, osgGA::GUIActionAdapter&)
{
    using E = osgGA::GUIEventAdapter;
    const auto type = ea.getEventType();
    double& factor = _node->settings.sampleDistanceFactor;  // voxels per step
    if (type == E::PUSH || type == E::DRAG || type == E::SCROLL) {
        _last = ea.getTime();
        if (!_lowered) {
            _full = factor;
            factor = _reduced = std::max(_full, std::min(2.0, 2.0 * _full));
            _lowered = true;
        }
    } else if (type == E::FRAME && _lowered && ea.getTime() - _last > _idle) {
        if (factor == _reduced) factor = _full;
        _lowered = false;
    }
    return false;  // the camera and the editor still get the event
}

}  // namespace volren
