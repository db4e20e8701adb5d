#pragma once
#include <string>

namespace volren {

/// An OpenGL 4.3+ context without any display: EGL's device platform on GPU machines,
/// Mesa's surfaceless platform (llvmpipe) elsewhere. $VOLREN_EGL_PLATFORM = device |
/// surfaceless forces one; $VOLREN_GL_PROFILE = core | compatibility forces the profile
/// (default: compatibility, else core). The context is current on the creating thread.
class HeadlessContext
{
public:
    /// Creates the context and makes it current; throws std::runtime_error saying what failed.
    HeadlessContext();
    ~HeadlessContext();
    HeadlessContext(const HeadlessContext&) = delete;
    HeadlessContext& operator=(const HeadlessContext&) = delete;

    /// Makes the context current on the calling thread.
    bool makeCurrent() const;
    /// Makes no context current on the calling thread (so another thread can take this one).
    bool release() const;
    /// "EGL <platform>: <GL_VERSION> / <GL_RENDERER>".
    const std::string& description() const { return _description; }
    /// Whether the context is a core profile (no fixed-function fallback).
    bool coreProfile() const { return _core; }

private:
    void* _display = nullptr;
    void* _context = nullptr;
    void* _surface = nullptr;
    bool _core = false;
    std::string _description;
};

}  // namespace volren
