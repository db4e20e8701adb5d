#include <volume_gui/InteractionQuality.h>

#include <algorithm>

namespace volren {

bool InteractionQuality::handle(const osgGA::GUIEventAdapter& ea, osgGA::GUIActionAdapter&)
{
    using E = osgGA::GUIEventAdapter;
    const auto type = ea.getEventType();
    int& lod = _node->settings.lod;
    if (type == E::PUSH || type == E::DRAG || type == E::SCROLL) {
        _last = ea.getTime();
        if (!_lowered) {
            _full = lod;
            lod = _reduced = std::min(_full + 1, 16);
            _lowered = true;
        }
    } else if (type == E::FRAME && _lowered && ea.getTime() - _last > _idle) {
        if (lod == _reduced) lod = _full;
        _lowered = false;
    }
    return false;  // the camera and the editor still get the event
}

}  // namespace volren
