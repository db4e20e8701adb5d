#pragma once
#include <volume_renderer/HeadlessContext.h>
#include <volume_renderer/VolumeScene.h>

#include <osg/Image>
#include <osgViewer/Viewer>

#include <memory>
#include <string>
#include <vector>

namespace volren {

/// Time one frame took. On GPUs gpuMs is the figure to compare; on Mesa llvmpipe the timer
/// query does not cover rasterisation (it reads ~7 ms for a 250 ms frame), so use drawMs there.
struct FrameTiming
{
    double cpuMs = 0.0;    ///< wall-clock milliseconds of viewer.frame() (cull, draw, read-back)
    double drawMs = -1.0;  ///< wall-clock milliseconds from the camera's first draw call to glFinish
    double gpuMs = -1.0;   ///< GL_TIME_ELAPSED of the camera's draw; negative when unavailable
    /// GL errors raised during the frame, as the driver's debug messages. In core profiles the
    /// one legacy call Debian's GL2-built OSG makes per frame is left out.
    std::vector<std::string> glErrors;
    /// Volumes the frame could not draw, and why (VolumeScene::drawErrors).
    std::vector<std::string> drawErrors;
};

/// Renders a scene with no display: a HeadlessContext drives an embedded osgViewer whose
/// camera draws into an RGBA32F framebuffer object that is read back after every frame.
class OffscreenRenderer
{
public:
    /// Creates the EGL context and the viewer; throws std::runtime_error on failure. With
    /// `samples` > 1 the camera draws into a multisampled framebuffer (as into an MSAA window;
    /// up to the driver's GL_MAX_SAMPLES), resolved before it is read back.
    OffscreenRenderer(int width, int height, int samples = 1);
    ~OffscreenRenderer();

    /// Sets the scene; a root that is not a VolumeScene is wrapped in one.
    void setScene(osg::Node* root);
    /// The VolumeScene at the root of the current scene.
    VolumeScene* volumeScene() { return _scene.get(); }
    /// The camera: set its view and projection matrices before rendering.
    osg::Camera* camera();
    /// Clear colour (the TF's background), linear RGB.
    void setBackground(const osg::Vec3& rgb);

    /// Renders one frame and reads it back; throws std::runtime_error on shader errors.
    FrameTiming renderFrame();
    /// Last frame: RGBA float, premultiplied over the background, row 0 at the bottom.
    const osg::Image* image() const { return _image.get(); }
    /// Last frame's depth buffer (window depth 0..1, row 0 at the bottom); null unless
    /// setReadDepth(true) was called before the frame.
    const osg::Image* depthImage() const { return _readDepth ? _depth.get() : nullptr; }
    /// Whether frames also read back the depth buffer (off by default: it costs a read-back).
    void setReadDepth(bool read);
    int samples() const { return _samples; }  ///< samples per pixel of the framebuffer

    /// OSG's state of the headless context (current on this thread).
    osg::State* state();
    /// Description of the GL context ("EGL surfaceless: OpenGL 4.5 ... / llvmpipe").
    const std::string& contextDescription() const { return _context->description(); }
    int width() const { return _width; }    ///< image width in pixels
    int height() const { return _height; }  ///< image height in pixels

private:
    struct GpuTimer;
    struct ErrorLog;
    void useCoreProfileDefaults();
    struct Multisampled;
    void attachBuffers();
    std::unique_ptr<HeadlessContext> _context;
    osg::ref_ptr<osgViewer::Viewer> _viewer;
    osg::ref_ptr<VolumeScene> _scene;
    osg::ref_ptr<osg::Image> _image;
    osg::ref_ptr<osg::Image> _depth;
    bool _readDepth = false;
    int _samples = 1;
    std::unique_ptr<Multisampled> _multisampled;  ///< the framebuffer of multisampled frames
    osg::ref_ptr<GpuTimer> _timer;
    std::unique_ptr<ErrorLog> _errors;
    int _width, _height;
};

}  // namespace volren
