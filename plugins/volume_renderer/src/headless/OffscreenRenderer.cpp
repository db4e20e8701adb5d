#include <volume_renderer/MatrixUniforms.h>
#include <volume_renderer/OffscreenRenderer.h>

#include <osg/GLExtensions>
#include <osgViewer/GraphicsWindow>
#include <osgUtil/RenderBin>
#include <osgViewer/Renderer>

#include <EGL/egl.h>

#include <chrono>
#include <cstring>
#include <stdexcept>

#ifndef GL_TIME_ELAPSED
#define GL_TIME_ELAPSED 0x88BF
#endif

namespace volren {

/// Brackets the camera's drawing with a GL_TIME_ELAPSED query.
struct OffscreenRenderer::GpuTimer : osg::Referenced
{
    GLuint query = 0;
    bool started = false;
    const osg::GLExtensions* ext = nullptr;
    std::chrono::steady_clock::time_point drawStart;
    double drawMs = -1.0;

    struct Begin : osg::Camera::DrawCallback
    {
        GpuTimer* timer;
        explicit Begin(GpuTimer* t) : timer(t) {}
        void operator()(osg::RenderInfo& info) const override
        {
            timer->drawStart = std::chrono::steady_clock::now();
            const osg::GLExtensions* ext = info.getState()->get<osg::GLExtensions>();
            if (!ext || !ext->glGenQueries || !ext->glGetQueryObjectui64v) return;
            timer->ext = ext;
            if (!timer->query) ext->glGenQueries(1, &timer->query);
            ext->glBeginQuery(GL_TIME_ELAPSED, timer->query);
            timer->started = true;
        }
    };
    struct End : osg::Camera::DrawCallback
    {
        GpuTimer* timer;
        explicit End(GpuTimer* t) : timer(t) {}
        void operator()(osg::RenderInfo&) const override
        {
            glFinish();  // software GL rasterises here: draw time must include it
            timer->drawMs =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - timer->drawStart).count();
            if (timer->started) timer->ext->glEndQuery(GL_TIME_ELAPSED);
        }
    };

    double collectMs()
    {
        if (!started) return -1.0;
        started = false;
        GLuint64 ns = 0;
        ext->glGetQueryObjectui64v(query, GL_QUERY_RESULT, &ns);  // waits for the GPU
        return double(ns) * 1e-6;
    }
};

/// Collects the driver's error messages through GL debug output (GL 4.3 core).
struct OffscreenRenderer::ErrorLog
{
    std::vector<std::string> messages;
    bool core = false;

    static void GL_APIENTRY callback(GLenum, GLenum type, GLuint, GLenum, GLsizei length, const GLchar* text,
                                     const void* self)
    {
        if (type != GL_DEBUG_TYPE_ERROR) return;
        auto* log = static_cast<ErrorLog*>(const_cast<void*>(self));
        std::string message(text, length > 0 ? std::size_t(length) : std::strlen(text));
        // Debian's OSG is a GL2 build: in core profiles it makes one legacy call per frame.
        if (log->core && message.find("unsupported function called") != std::string::npos) return;
        log->messages.push_back(message);
    }

    void install(bool coreProfile)
    {
        core = coreProfile;
        using Install = void(GL_APIENTRY*)(void(GL_APIENTRY*)(GLenum, GLenum, GLuint, GLenum, GLsizei, const GLchar*,
                                                               const void*),
                                            const void*);
        auto install = reinterpret_cast<Install>(eglGetProcAddress("glDebugMessageCallback"));
        if (!install) return;
        glEnable(GL_DEBUG_OUTPUT);
        glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
        install(&ErrorLog::callback, this);
    }
};

OffscreenRenderer::OffscreenRenderer(int width, int height, int samples) : _samples(samples), _width(width), _height(height)
{
    if (width <= 0 || height <= 0 || width > 16384 || height > 16384)
        throw std::runtime_error("image size must be 1..16384 pixels per side, got " + std::to_string(width) + "x" +
                                 std::to_string(height));
    if (samples < 1 || samples > 64) throw std::runtime_error("samples must be 1..64, got " + std::to_string(samples));
    _context = std::make_unique<HeadlessContext>();
    _errors = std::make_unique<ErrorLog>();
    _errors->install(_context->coreProfile());

    _viewer = new osgViewer::Viewer;
    _viewer->setThreadingModel(osgViewer::ViewerBase::SingleThreaded);
    // OSG pins a single-threaded viewer's thread to CPU 0, and every thread started after it
    // (reference workers, brick loaders) inherits the pin: one core for all of them.
    _viewer->setUseConfigureAffinity(false);
    _viewer->setUpViewerAsEmbeddedInWindow(0, 0, width, height);
    _viewer->setKeyEventSetsDone(0);
    _viewer->setQuitEventSetsDone(false);
    _viewer->setReleaseContextAtEndOfFrameHint(false);
    // A core profile has no fixed-function lighting: no viewer headlight there (volumes use
    // the scene's own LightSources through their shaders).
    if (_context->coreProfile()) _viewer->setLightingMode(osg::View::NO_LIGHT);

    osg::Camera* cam = _viewer->getCamera();
    osg::State* state = cam->getGraphicsContext()->getState();
    // A core profile needs OSG to feed osg_Vertex and the osg_*Matrix uniforms. A compatibility
    // context keeps OSG's defaults, as stock viewers do, so that fixed-function polygon models get
    // their normals and colours; the volume proxies feed their own matrix then (MatrixUniforms).
    if (_context->coreProfile()) {
        state->setUseModelViewAndProjectionUniforms(true);
        state->setUseVertexAttributeAliasing(true);
    }

    _image = new osg::Image;
    _image->allocateImage(width, height, 1, GL_RGBA, GL_FLOAT);
    _image->setInternalTextureFormat(GL_RGBA32F_ARB);
    cam->setViewport(0, 0, width, height);
    _depth = new osg::Image;
    _depth->allocateImage(width, height, 1, GL_DEPTH_COMPONENT, GL_FLOAT);
    _depth->setInternalTextureFormat(GL_DEPTH_COMPONENT24);
    attachBuffers();
    cam->setClearColor(osg::Vec4(0.0f, 0.0f, 0.0f, 0.0f));
    cam->setProjectionMatrixAsPerspective(30.0, double(width) / height, 0.1, 1000.0);
    // No small-feature culling: in a 1x1 image a volume filling the view projects to one pixel,
    // below OSG's threshold, and was culled (nothing drawn).
    cam->setCullingMode(cam->getCullingMode() & ~osg::CullSettings::SMALL_FEATURE_CULLING);

    _timer = new GpuTimer;
    cam->setInitialDrawCallback(new GpuTimer::Begin(_timer.get()));
    cam->setFinalDrawCallback(new GpuTimer::End(_timer.get()));

    _scene = new VolumeScene;
    _viewer->setSceneData(_scene.get());
    _viewer->realize();
    // GL errors are read once per frame by renderFrame() (OSG's own per-bin polling would
    // swallow them into log lines).
    state->setCheckForGLErrors(osg::State::NEVER_CHECK_GL_ERRORS);
    if (_context->coreProfile()) useCoreProfileDefaults();
}

void OffscreenRenderer::useCoreProfileDefaults()
{
    // OSG's GL2 build puts fixed-function defaults (Material, AlphaFunc, LightModel) into the
    // camera's and each SceneView's global state; a core profile rejects them, so keep only
    // what the GLSL pipeline needs.
    // Debian's OSG is a GL2 build that also issues legacy matrix calls (glLoadMatrix), which only
    // raise GL error flags in a core profile; its per-state error polling would log them every
    // frame, so it is off here. Our own shader failures are still caught by checkPrograms().
    _viewer->getCamera()->getGraphicsContext()->getState()->setCheckForGLErrors(osg::State::NEVER_CHECK_GL_ERRORS);
    osg::ref_ptr<osg::StateSet> cameraState = new osg::StateSet;
    cameraState->setMode(GL_DEPTH_TEST, osg::StateAttribute::ON);
    _viewer->getCamera()->setStateSet(cameraState.get());
    // The DepthSortedBin prototype carries an AlphaFunc in fixed-function builds (process-wide;
    // meaningless for GLSL, which never reads it).
    if (osgUtil::RenderBin* sorted = osgUtil::RenderBin::getRenderBinPrototype("DepthSortedBin"))
        sorted->setStateSet(nullptr);
    auto* renderer = dynamic_cast<osgViewer::Renderer*>(_viewer->getCamera()->getRenderer());
    if (!renderer) return;
    for (unsigned int i = 0; i < 2; ++i) {
        osgUtil::SceneView* view = renderer->getSceneView(i);
        if (!view) continue;
        osg::ref_ptr<osg::StateSet> defaults = new osg::StateSet;
        defaults->setMode(GL_DEPTH_TEST, osg::StateAttribute::ON);
        view->setGlobalStateSet(defaults.get());
    }
}

OffscreenRenderer::~OffscreenRenderer()
{
    if (_viewer) {
        _context->makeCurrent();
        _multisampled.reset();
        _viewer->setSceneData(nullptr);
        _scene = nullptr;
        _viewer->getCamera()->getGraphicsContext()->close(true);  // releases GL objects while current
        _viewer = nullptr;
    }
}

void OffscreenRenderer::setReadDepth(bool read)
{
    if (read == _readDepth) return;
    _readDepth = read;
    attachBuffers();
}

/// A multisampled framebuffer the camera draws into as into an MSAA window's (it is the
/// context's default framebuffer meanwhile), and a single-sampled one it is resolved into and
/// read back from. Raw GL: OSG 3.6's own multisampled camera FBO is incomplete on Mesa.
struct OffscreenRenderer::Multisampled
{
    const osg::GLExtensions* ext;
    GLuint fbo[2] = {0, 0};               ///< multisampled, resolved
    GLuint buffers[4] = {0, 0, 0, 0};     ///< colour and depth of each

    Multisampled(const osg::GLExtensions* extensions, int width, int height, int samples) : ext(extensions)
    {
        if (!ext->glBlitFramebuffer || !ext->glRenderbufferStorageMultisample)
            throw std::runtime_error("multisampling needs framebuffer blits and multisampled renderbuffers");
        GLint most = 0;
        glGetIntegerv(GL_MAX_SAMPLES, &most);
        if (samples > most)
            throw std::runtime_error(std::to_string(samples) + " samples asked, the driver offers at most " +
                                     std::to_string(most));
        ext->glGenFramebuffers(2, fbo);
        ext->glGenRenderbuffers(4, buffers);
        for (int i = 0; i < 2; ++i) {
            const GLsizei n = i == 0 ? samples : 0;
            ext->glBindRenderbuffer(GL_RENDERBUFFER_EXT, buffers[2 * i]);
            ext->glRenderbufferStorageMultisample(GL_RENDERBUFFER_EXT, n, GL_RGBA32F_ARB, width, height);
            ext->glBindRenderbuffer(GL_RENDERBUFFER_EXT, buffers[2 * i + 1]);
            ext->glRenderbufferStorageMultisample(GL_RENDERBUFFER_EXT, n, GL_DEPTH_COMPONENT24, width, height);
            ext->glBindFramebuffer(GL_FRAMEBUFFER_EXT, fbo[i]);
            ext->glFramebufferRenderbuffer(GL_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT0_EXT, GL_RENDERBUFFER_EXT, buffers[2 * i]);
            ext->glFramebufferRenderbuffer(GL_FRAMEBUFFER_EXT, GL_DEPTH_ATTACHMENT_EXT, GL_RENDERBUFFER_EXT,
                                           buffers[2 * i + 1]);
            const GLenum status = ext->glCheckFramebufferStatus(GL_FRAMEBUFFER_EXT);
            if (status != GL_FRAMEBUFFER_COMPLETE_EXT) {
                release();
                throw std::runtime_error("multisampled framebuffer incomplete (status " + std::to_string(status) + ")");
            }
        }
        ext->glBindRenderbuffer(GL_RENDERBUFFER_EXT, 0);
        ext->glBindFramebuffer(GL_FRAMEBUFFER_EXT, fbo[0]);
    }
    ~Multisampled() { release(); }

    void release()
    {
        ext->glBindFramebuffer(GL_FRAMEBUFFER_EXT, 0);
        ext->glDeleteFramebuffers(2, fbo);
        ext->glDeleteRenderbuffers(4, buffers);
        fbo[0] = fbo[1] = 0;
    }

    /// Resolves the frame and reads it into `colour` (RGBA float) and `depth` (when given).
    void read(int width, int height, osg::Image& colour, osg::Image* depth) const
    {
        ext->glBindFramebuffer(GL_READ_FRAMEBUFFER_EXT, fbo[0]);
        ext->glBindFramebuffer(GL_DRAW_FRAMEBUFFER_EXT, fbo[1]);
        ext->glBlitFramebuffer(0, 0, width, height, 0, 0, width, height,
                               GL_COLOR_BUFFER_BIT | (depth ? GL_DEPTH_BUFFER_BIT : 0), GL_NEAREST);
        ext->glBindFramebuffer(GL_READ_FRAMEBUFFER_EXT, fbo[1]);
        glReadBuffer(GL_COLOR_ATTACHMENT0_EXT);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, colour.data());
        colour.dirty();
        if (depth) {
            glReadPixels(0, 0, width, height, GL_DEPTH_COMPONENT, GL_FLOAT, depth->data());
            depth->dirty();
        }
        ext->glBindFramebuffer(GL_FRAMEBUFFER_EXT, fbo[0]);
    }
};

void OffscreenRenderer::attachBuffers()
{
    // Single-sampled frames draw into OSG's camera FBO and are read straight into the images.
    // Multisampled ones draw into the Multisampled framebuffer, made the context's default (set
    // once: OSG's render stage does not switch between the two ways).
    osg::Camera* cam = _viewer->getCamera();
    if (_samples > 1) {
        if (_multisampled) return;  // reads the depth when asked, with no change of attachments
        osg::GraphicsContext* gc = cam->getGraphicsContext();
        if (!_context->makeCurrent()) throw std::runtime_error("EGL: cannot make the context current");
        _multisampled = std::make_unique<Multisampled>(osg::GLExtensions::Get(gc->getState()->getContextID(), true),
                                                       _width, _height, _samples);
        gc->setDefaultFboId(_multisampled->fbo[0]);
        cam->setRenderTargetImplementation(osg::Camera::FRAME_BUFFER);
        cam->setDrawBuffer(GL_COLOR_ATTACHMENT0_EXT);
        cam->setReadBuffer(GL_COLOR_ATTACHMENT0_EXT);
        return;
    }
    cam->detach(osg::Camera::COLOR_BUFFER);
    cam->detach(osg::Camera::DEPTH_BUFFER);
    cam->setRenderTargetImplementation(osg::Camera::FRAME_BUFFER_OBJECT);
    cam->attach(osg::Camera::COLOR_BUFFER, _image.get());
    if (_readDepth) cam->attach(osg::Camera::DEPTH_BUFFER, _depth.get());
    else cam->attach(osg::Camera::DEPTH_BUFFER, GL_DEPTH_COMPONENT24);
    cam->dirtyAttachmentMap();
}


void OffscreenRenderer::setScene(osg::Node* root)
{
    osg::ref_ptr<VolumeScene> scene = dynamic_cast<VolumeScene*>(root);
    if (!scene) {
        scene = new VolumeScene;
        if (root) scene->addChild(root);
    }
    _scene = scene;
    _viewer->setSceneData(_scene.get());
    // The old scene's arrays may be freed now, and new ones allocated at their addresses.
    if (_context->makeCurrent()) forgetClientArrays(*state());
}

osg::State* OffscreenRenderer::state()
{
    return _viewer->getCamera()->getGraphicsContext()->getState();
}

osg::Camera* OffscreenRenderer::camera()
{
    return _viewer->getCamera();
}

void OffscreenRenderer::setBackground(const osg::Vec3& rgb)
{
    // Alpha 0: the image's alpha channel is the scene's own coverage.
    _viewer->getCamera()->setClearColor(osg::Vec4(rgb, 0.0f));
}

FrameTiming OffscreenRenderer::renderFrame()
{
    if (!_context->makeCurrent()) throw std::runtime_error("EGL: cannot make the context current");
    FrameTiming timing;
    const auto start = std::chrono::steady_clock::now();
    while (glGetError() != GL_NO_ERROR) {}  // flags of earlier, unrelated calls
    _errors->messages.clear();
    if (_multisampled) _multisampled->ext->glBindFramebuffer(GL_FRAMEBUFFER_EXT, _multisampled->fbo[0]);
    _viewer->frame();
    if (_multisampled) _multisampled->read(_width, _height, *_image, _readDepth ? _depth.get() : nullptr);
    timing.gpuMs = _timer->collectMs();
    while (glGetError() != GL_NO_ERROR) {}
    timing.glErrors = _errors->messages;
    timing.drawMs = _timer->drawMs;
    timing.cpuMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    // The draw the query timed ran, and was waited for, within this wall time: a longer GPU time
    // cannot be true (llvmpipe returned 2,043,847 ms for a 140 ms draw), so it is unavailable.
    if (timing.gpuMs > timing.cpuMs) timing.gpuMs = -1.0;
    // Every frame: a program first used in this frame (a new composition) is checked as it is.
    _scene->checkPrograms(*_viewer->getCamera()->getGraphicsContext()->getState());
    timing.drawErrors = _scene->drawErrors();
    return timing;
}

}  // namespace volren
