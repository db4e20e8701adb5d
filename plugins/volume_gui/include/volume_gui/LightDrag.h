#pragma once
#include <osg/Camera>
#include <osg/LightSource>
#include <osgGA/GUIEventHandler>

#include <vector>

namespace volren {

/// `volren view`'s light control: a left-button drag with Ctrl held turns every light of the
/// scene about the view's axes (horizontal motion about the view's up axis, vertical about its
/// right axis; a drag across the whole window is a half turn). Directional lights turn their
/// direction; point lights move on a sphere about the scene's centre. Headlights (absolute
/// reference frame) turn in eye coordinates, other lights in their own. The drag is consumed:
/// the camera stays still. Shadowing that keeps data per light (a light volume) rebuilds.
class LightDrag : public osgGA::GUIEventHandler
{
public:
    LightDrag(osg::Node* scene, osg::Camera* camera) : _scene(scene), _camera(camera) {}
    bool handle(const osgGA::GUIEventAdapter& ea, osgGA::GUIActionAdapter& aa) override;

    /// The rotation, in eye coordinates, of a drag by (dx, dy) in normalised window units
    /// ([-1, 1] across the window): dx * pi/2 about the eye's y axis, dy * pi/2 about its -x axis.
    static osg::Matrixd eyeRotation(double dx, double dy);
    /// `position` (w = 0 direction, w = 1 point) in a frame whose coordinates map to eye
    /// coordinates by `toEye`, turned by `eyeRotation` about `pivot` (eye coordinates).
    static osg::Vec4d turned(const osg::Vec4d& position, const osg::Matrixd& toEye, const osg::Matrixd& eyeRotation,
                             const osg::Vec3d& pivot);

private:
    struct Held
    {
        osg::ref_ptr<osg::LightSource> source;
        osg::Vec4d start;     ///< position when the drag began
        osg::Matrixd toEye;   ///< the light's frame -> eye coordinates at the drag's start
    };
    osg::ref_ptr<osg::Node> _scene;
    osg::observer_ptr<osg::Camera> _camera;
    std::vector<Held> _held;
    osg::Vec3d _pivot;  ///< the scene's centre in eye coordinates
    float _x0 = 0.0f, _y0 = 0.0f;
    bool _dragging = false;
};

}  // namespace volren
