#include <volume_renderer/GraphicsDriver.h>
#include <volume_renderer/HeadlessContext.h>

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/gl.h>

#include <osg/Notify>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <vector>

namespace volren {

namespace {

std::string eglErrorText()
{
    char buf[32];
    std::snprintf(buf, sizeof(buf), "0x%04x", unsigned(eglGetError()));
    return buf;
}

template <typename F>
F eglProc(const char* name)
{
    return reinterpret_cast<F>(eglGetProcAddress(name));
}

/// First EGL display of a hardware device (skipping Mesa's software device), or none.
EGLDisplay openDeviceDisplay(PFNEGLGETPLATFORMDISPLAYEXTPROC getPlatformDisplay)
{
    auto queryDevices = eglProc<PFNEGLQUERYDEVICESEXTPROC>("eglQueryDevicesEXT");
    auto queryDeviceString = eglProc<PFNEGLQUERYDEVICESTRINGEXTPROC>("eglQueryDeviceStringEXT");
    if (!queryDevices || !getPlatformDisplay) return EGL_NO_DISPLAY;
    EGLint count = 0;
    if (!queryDevices(0, nullptr, &count) || count <= 0) return EGL_NO_DISPLAY;
    std::vector<EGLDeviceEXT> devices(static_cast<std::size_t>(count));
    queryDevices(count, devices.data(), &count);
    for (EGLint i = 0; i < count; ++i) {
        const char* ext = queryDeviceString ? queryDeviceString(devices[i], EGL_EXTENSIONS) : nullptr;
        if (ext && std::strstr(ext, "EGL_MESA_device_software")) continue;
        EGLDisplay display = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
        if (display != EGL_NO_DISPLAY && eglInitialize(display, nullptr, nullptr)) return display;
    }
    return EGL_NO_DISPLAY;
}

}  // namespace

HeadlessContext::HeadlessContext()
{
    auto getPlatformDisplay = eglProc<PFNEGLGETPLATFORMDISPLAYEXTPROC>("eglGetPlatformDisplayEXT");
    const char* forced = std::getenv("VOLREN_EGL_PLATFORM");
    const std::string platform = forced ? forced : "";
    if (!platform.empty() && platform != "device" && platform != "surfaceless")
        throw std::runtime_error("VOLREN_EGL_PLATFORM must be 'device' or 'surfaceless', got '" + platform + "'");

    EGLDisplay display = EGL_NO_DISPLAY;
    std::string used;
    if (platform.empty() || platform == "device") {
        display = openDeviceDisplay(getPlatformDisplay);
        used = "device";
    }
    if (display == EGL_NO_DISPLAY && (platform.empty() || platform == "surfaceless") && getPlatformDisplay) {
        display = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (display != EGL_NO_DISPLAY && !eglInitialize(display, nullptr, nullptr)) display = EGL_NO_DISPLAY;
        used = "surfaceless";
    }
    if (display == EGL_NO_DISPLAY)
        throw std::runtime_error("no headless EGL display (tried " + (platform.empty() ? std::string("device, surfaceless") : platform) +
                                 "; EGL error " + eglErrorText() + "): install libegl-mesa0 and libgl1-mesa-dri, or a GPU driver");
    _display = display;

    if (!eglBindAPI(EGL_OPENGL_API)) throw std::runtime_error("EGL: desktop OpenGL API not available");
    const EGLint configAttribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE, EGL_PBUFFER_BIT,
                                    EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8, EGL_ALPHA_SIZE, 8,
                                    EGL_DEPTH_SIZE, 24, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint configs = 0;
    if (!eglChooseConfig(display, configAttribs, &config, 1, &configs) || configs == 0) {
        const EGLint anyAttribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
        if (!eglChooseConfig(display, anyAttribs, &config, 1, &configs) || configs == 0)
            throw std::runtime_error("EGL: no OpenGL-capable config (" + eglErrorText() + ")");
    }

    // Prefer a compatibility context (OSG 3.6 issues some legacy calls); fall back to core.
    // $VOLREN_GL_PROFILE = core | compatibility allows only that profile.
    const char* profileEnv = std::getenv("VOLREN_GL_PROFILE");
    const std::string profile = profileEnv ? profileEnv : "";
    if (!profile.empty() && profile != "core" && profile != "compatibility")
        throw std::runtime_error("VOLREN_GL_PROFILE must be 'core' or 'compatibility', got '" + profile + "'");
    struct Attempt { EGLint major, minor, profile; };
    const Attempt attempts[] = {{4, 5, EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT},
                                {4, 3, EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT},
                                {4, 5, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT},
                                {4, 3, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT}};
    EGLContext context = EGL_NO_CONTEXT;
    for (const Attempt& a : attempts) {
        const bool core = a.profile == EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT;
        if ((profile == "core" && !core) || (profile == "compatibility" && core)) continue;
        const EGLint attribs[] = {EGL_CONTEXT_MAJOR_VERSION, a.major, EGL_CONTEXT_MINOR_VERSION, a.minor,
                                  EGL_CONTEXT_OPENGL_PROFILE_MASK, a.profile, EGL_NONE};
        context = eglCreateContext(display, config, EGL_NO_CONTEXT, attribs);
        if (context != EGL_NO_CONTEXT) {
            _core = a.profile == EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT;
            break;
        }
    }
    if (context == EGL_NO_CONTEXT)
        throw std::runtime_error("EGL: cannot create an OpenGL 4.3+ context (" + eglErrorText() + ")");
    _context = context;

    if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
        // Without EGL_KHR_surfaceless_context a tiny pbuffer stands in; rendering goes to FBOs anyway.
        const EGLint pbufferAttribs[] = {EGL_WIDTH, 1, EGL_HEIGHT, 1, EGL_NONE};
        EGLSurface surface = eglCreatePbufferSurface(display, config, pbufferAttribs);
        if (surface == EGL_NO_SURFACE || !eglMakeCurrent(display, surface, surface, context))
            throw std::runtime_error("EGL: cannot make the context current (" + eglErrorText() + ")");
        _surface = surface;
    }

    const char* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    _description = "EGL " + used + ": OpenGL " + (version ? version : "?") + (_core ? " core profile" : "") + " / " +
                   (renderer ? renderer : "?");
    OSG_INFO << "volren: " << _description << std::endl;
    recordGraphicsDriver(renderer ? renderer : "");
    GLint largest = 0, kilobytes = 0;
    glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &largest);
    glGetIntegerv(0x9047, &kilobytes);  // GL_GPU_MEMORY_INFO_DEDICATED_VIDMEM_NVX: an error elsewhere
    while (glGetError() != GL_NO_ERROR) {
    }
    recordGraphicsLimits(largest, std::size_t(std::max<GLint>(kilobytes, 0)) * 1024);
}

HeadlessContext::~HeadlessContext()
{
    if (!_display) return;
    eglMakeCurrent(_display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (_surface) eglDestroySurface(_display, _surface);
    if (_context) eglDestroyContext(_display, _context);
    eglReleaseThread();  // displays are shared per platform: never terminate one another context uses
}

bool HeadlessContext::makeCurrent() const
{
    return eglMakeCurrent(_display, _surface ? _surface : EGL_NO_SURFACE, _surface ? _surface : EGL_NO_SURFACE,
                          _context) == EGL_TRUE;
}

bool HeadlessContext::release() const
{
    return eglMakeCurrent(_display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT) == EGL_TRUE;
}

}  // namespace volren
