#include <volume_gui/LightDrag.h>

#include <osg/ComputeBoundsVisitor>
#include <osg/NodeVisitor>

#include <cmath>

namespace volren {

namespace {

/// Every LightSource below a node, with the path to it.
struct LightFinder : osg::NodeVisitor
{
    LightFinder() : osg::NodeVisitor(TRAVERSE_ACTIVE_CHILDREN) {}
    void apply(osg::LightSource& source) override
    {
        if (source.getLight()) found.push_back({&source, osg::computeLocalToWorld(getNodePath())});
        traverse(source);
    }
    std::vector<std::pair<osg::LightSource*, osg::Matrixd>> found;  ///< source, its local -> world
};

}  // namespace

osg::Matrixd LightDrag::eyeRotation(double dx, double dy)
{
    return osg::Matrixd::rotate(dx * osg::PI_2, osg::Vec3d(0, 1, 0)) * osg::Matrixd::rotate(-dy * osg::PI_2, osg::Vec3d(1, 0, 0));
}

osg::Vec4d LightDrag::turned(const osg::Vec4d& position, const osg::Matrixd& toEye, const osg::Matrixd& eyeRotation,
                             const osg::Vec3d& pivot)
{
    // Row vectors: frame -> eye, about the pivot, back to the frame. Directions (w = 0) ignore
    // every translation on the way.
    const osg::Matrixd aboutPivot = osg::Matrixd::translate(-pivot) * eyeRotation * osg::Matrixd::translate(pivot);
    return position * (toEye * aboutPivot * osg::Matrixd::inverse(toEye));
}

bool LightDrag::handle(const osgGA::GUIEventAdapter& ea, osgGA::GUIActionAdapter&)
{
    using E = osgGA::GUIEventAdapter;
    if (ea.getHandled()) return false;
    const bool ctrl = (ea.getModKeyMask() & E::MODKEY_CTRL) != 0;
    switch (ea.getEventType()) {
    case E::PUSH: {
        if (!ctrl || ea.getButton() != E::LEFT_MOUSE_BUTTON || !_camera.valid()) return false;
        const osg::Matrixd view = _camera->getViewMatrix();
        LightFinder finder;
        _scene->accept(finder);
        _held.clear();
        for (const auto& [source, localToWorld] : finder.found) {
            const bool eye = source->getReferenceFrame() == osg::LightSource::ABSOLUTE_RF;
            _held.push_back({source, osg::Vec4d(source->getLight()->getPosition()), eye ? osg::Matrixd() : localToWorld * view});
        }
        osg::ComputeBoundsVisitor bounds;
        _scene->accept(bounds);
        _pivot = bounds.getBoundingBox().valid() ? osg::Vec3d(bounds.getBoundingBox().center()) * view : osg::Vec3d();
        _x0 = ea.getXnormalized();
        _y0 = ea.getYnormalized();
        _dragging = true;
        return true;
    }
    case E::DRAG: {
        if (!_dragging) return false;
        const osg::Matrixd rotation = eyeRotation(ea.getXnormalized() - _x0, ea.getYnormalized() - _y0);
        for (const Held& h : _held) h.source->getLight()->setPosition(osg::Vec4(turned(h.start, h.toEye, rotation, _pivot)));
        return true;
    }
    case E::RELEASE:
        if (!_dragging) return false;
        _dragging = false;
        _held.clear();
        return true;
    default:
        return false;
    }
}

}  // namespace volren
