#pragma once
#include <osg/Geode>
#include <osgGA/GUIEventHandler>

#include <functional>

struct ImGuiContext;
struct ImGuiIO;

namespace volren {

/// Dear ImGui drawn through OSG, over the scene: a node (render bin 1000, after the volumes'
/// bin 10, no depth test) whose drawable runs one ImGui frame per draw — `ui` builds the widgets —
/// and renders it with ImGui's OpenGL 3 backend, which saves and restores the GL state it
/// touches. Input comes from eventHandler() (mouse, wheel, keys, text from an osgViewer), or, in
/// headless tests, from `beforeFrame`, which may set ImGuiIO directly before each frame.
/// One ImGui context per overlay; one GL context (the first that draws it).
class ImGuiOverlay : public osg::Referenced
{
public:
    explicit ImGuiOverlay(std::function<void()> ui);

    /// The node to add to the scene (under the VolumeScene: its render bin keeps it out of the
    /// opaque geometry the volumes are mixed with).
    osg::Node* node() { return _geode.get(); }
    /// Feeds an osgViewer's events to ImGui; consumes those ImGui wants (a drag on the editor
    /// does not turn the camera).
    osgGA::GUIEventHandler* eventHandler();
    /// This overlay's ImGui context.
    ImGuiContext* context() const { return _context; }
    /// Called at the start of every frame with the context current (tests: synthetic input).
    std::function<void(ImGuiIO&)> beforeFrame;
    /// Frames drawn so far.
    unsigned int frames() const { return _frames; }

protected:
    ~ImGuiOverlay() override;

private:
    class Drawable;
    class Handler;
    std::function<void()> _ui;
    ImGuiContext* _context = nullptr;
    osg::ref_ptr<osg::Geode> _geode;
    osg::ref_ptr<Handler> _handler;
    unsigned int _frames = 0;
    bool _initialised = false;
    double _lastTime = -1.0;
};

}  // namespace volren
