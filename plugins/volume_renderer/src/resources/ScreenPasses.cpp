#include <volume_renderer/ScreenPasses.h>
#include <volume_renderer/ShaderFunctionRegistry.h>

#include <osg/BindImageTexture>
#include <osg/ColorMask>
#include <osg/CullFace>
#include <osg/Depth>
#include <osg/GLExtensions>
#include <osg/Geode>

#include <map>
#include <stdexcept>

#ifndef GL_SHADER_IMAGE_ACCESS_BARRIER_BIT
#define GL_SHADER_IMAGE_ACCESS_BARRIER_BIT 0x00000020
#endif

namespace volren {

namespace {

/// Copies the depth buffer of the current viewport into a depth texture of the same size. A
/// multisampled framebuffer (MSAA window, multisampled camera FBO) cannot be copied from: it is
/// resolved into the texture by a blit, which needs the texture in the framebuffer's depth format.
class DepthCopy : public osg::Drawable
{
public:
    explicit DepthCopy(osg::Texture2D* texture) : _texture(texture)
    {
        setCullingActive(false);
        setUseDisplayList(false);
    }
    DepthCopy(const DepthCopy& other, const osg::CopyOp& op) : osg::Drawable(other, op), _texture(other._texture) {}
    META_Object(volren, DepthCopy)

    void drawImplementation(osg::RenderInfo& info) const override
    {
        osg::State& state = *info.getState();
        const osg::Viewport* vp = state.getCurrentViewport();
        if (!vp || int(vp->width()) != _texture->getTextureWidth() || int(vp->height()) != _texture->getTextureHeight())
            return;  // sized at cull time; a mismatch means this camera's viewport changed since
        const GLint x = GLint(vp->x()), y = GLint(vp->y());
        const GLsizei w = GLsizei(vp->width()), h = GLsizei(vp->height());
        GLint sampleBuffers = 0;
        glGetIntegerv(GL_SAMPLE_BUFFERS, &sampleBuffers);
        const osg::GLExtensions* ext = state.get<osg::GLExtensions>();
        if (sampleBuffers == 0 || !ext->glBlitFramebuffer) {
            state.applyTextureAttribute(0, _texture.get());  // allocates the storage on first use
            glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, x, y, w, h);
            return;
        }
        GLint readFbo = 0, drawFbo = 0;
        glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &readFbo);
        glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawFbo);
        const GLenum format = depthFormatOf(readFbo != 0);
        if (GLenum(_texture->getInternalFormat()) != format) {  // this camera's texture, drawn only here
            _texture->setInternalFormat(GLint(format));
            _texture->setSourceFormat(format == GL_DEPTH24_STENCIL8 || format == GL_DEPTH32F_STENCIL8 ? GL_DEPTH_STENCIL
                                                                                                   : GL_DEPTH_COMPONENT);
            _texture->dirtyTextureObject();
        }
        state.applyTextureAttribute(0, _texture.get());
        GLuint& fbo = _resolve[state.getContextID()];
        if (!fbo) ext->glGenFramebuffers(1, &fbo);
        ext->glBindFramebuffer(GL_DRAW_FRAMEBUFFER_EXT, fbo);
        const GLenum attachment = _texture->getSourceFormat() == GL_DEPTH_STENCIL ? GL_DEPTH_STENCIL_ATTACHMENT
                                                                                 : GL_DEPTH_ATTACHMENT_EXT;
        ext->glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER_EXT, attachment, GL_TEXTURE_2D,
                                    _texture->getTextureObject(state.getContextID())->id(), 0);
        glDrawBuffer(GL_NONE);
        ext->glBlitFramebuffer(x, y, x + w, y + h, 0, 0, w, h, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
        ext->glBindFramebuffer(GL_DRAW_FRAMEBUFFER_EXT, GLuint(drawFbo));
    }

    void releaseGLObjects(osg::State* state) const override
    {
        osg::Drawable::releaseGLObjects(state);
        if (!state) return;  // the ids die with their contexts
        auto it = _resolve.find(state->getContextID());
        if (it == _resolve.end()) return;
        if (const osg::GLExtensions* ext = state->get<osg::GLExtensions>()) ext->glDeleteFramebuffers(1, &it->second);
        _resolve.erase(it);
    }

private:
    DepthCopy() = default;

    /// The sized depth format of the bound read framebuffer (an FBO's depth attachment, or the
    /// window's depth buffer).
    static GLenum depthFormatOf(bool fbo)
    {
        // GL 3.0, which OSG's GLExtensions does not load.
        using Query = void(GL_APIENTRY*)(GLenum, GLenum, GLenum, GLint*);
        static const auto query = reinterpret_cast<Query>(osg::getGLExtensionFuncPtr("glGetFramebufferAttachmentParameteriv"));
        if (!query) return GL_DEPTH_COMPONENT24;
        GLint depthBits = 24, stencilBits = 0, type = GL_UNSIGNED_NORMALIZED;
        const GLenum depth = fbo ? GL_DEPTH_ATTACHMENT_EXT : GLenum(GL_DEPTH);
        const GLenum stencil = fbo ? GL_STENCIL_ATTACHMENT_EXT : GLenum(GL_STENCIL);
        query(GL_READ_FRAMEBUFFER_EXT, depth, GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE, &depthBits);
        query(GL_READ_FRAMEBUFFER_EXT, depth, GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE, &type);
        GLint stencilType = GL_NONE;
        query(GL_READ_FRAMEBUFFER_EXT, stencil, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &stencilType);
        if (stencilType != GL_NONE)
            query(GL_READ_FRAMEBUFFER_EXT, stencil, GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE,
                                                      &stencilBits);
        if (type == GL_FLOAT) return stencilBits ? GL_DEPTH32F_STENCIL8 : GL_DEPTH_COMPONENT32F;
        if (stencilBits) return GL_DEPTH24_STENCIL8;
        return depthBits > 24 ? GL_DEPTH_COMPONENT32 : depthBits > 16 ? GL_DEPTH_COMPONENT24 : GL_DEPTH_COMPONENT16;
    }

    osg::ref_ptr<osg::Texture2D> _texture;
    mutable std::map<unsigned int, GLuint> _resolve;  ///< resolve FBO per context
};

/// Makes the image writes of the entry passes visible to the ray casters drawn after it.
class ImageBarrier : public osg::Drawable
{
public:
    ImageBarrier()
    {
        setCullingActive(false);
        setUseDisplayList(false);
    }
    ImageBarrier(const ImageBarrier& other, const osg::CopyOp& op) : osg::Drawable(other, op) {}
    META_Object(volren, ImageBarrier)

    void drawImplementation(osg::RenderInfo& info) const override
    {
        const osg::GLExtensions* ext = info.getState()->get<osg::GLExtensions>();
        if (ext && ext->glMemoryBarrier) ext->glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    }
};

osg::ref_ptr<osg::Texture2D> screenTexture(GLint internalFormat, GLenum sourceFormat)
{
    osg::ref_ptr<osg::Texture2D> t = new osg::Texture2D;
    t->setInternalFormat(internalFormat);
    t->setSourceFormat(sourceFormat);
    t->setSourceType(GL_FLOAT);
    t->setFilter(osg::Texture::MIN_FILTER, osg::Texture::NEAREST);  // no mipmaps: complete for texelFetch
    t->setFilter(osg::Texture::MAG_FILTER, osg::Texture::NEAREST);
    t->setWrap(osg::Texture::WRAP_S, osg::Texture::CLAMP_TO_EDGE);  // OSG's default CLAMP is not core GL
    t->setWrap(osg::Texture::WRAP_T, osg::Texture::CLAMP_TO_EDGE);
    t->setResizeNonPowerOfTwoHint(false);
    t->setDataVariance(osg::Object::DYNAMIC);
    return t;
}

/// Resizes `t` to `w` x `h` (its GL storage is re-made on next use).
void fit(osg::Texture2D& t, int w, int h)
{
    if (t.getTextureWidth() == w && t.getTextureHeight() == h) return;
    t.setTextureSize(w, h);
    t.dirtyTextureObject();
}

}  // namespace

struct ScreenPasses::Capture
{
    osg::ref_ptr<osg::Texture2D> texture = screenTexture(GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT);
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    osg::ref_ptr<osg::Uniform> origin = new osg::Uniform("volren_viewportOrigin", osg::Vec2f());
    std::map<int, osg::ref_ptr<osg::StateSet>> stateByUnit;
    unsigned int lastCull = 0, scheduled = 0;
};

struct ScreenPasses::Entry
{
    osg::ref_ptr<osg::Texture2D> texture = screenTexture(GL_RGBA32F_ARB, GL_RGBA);
    osg::ref_ptr<osg::MatrixTransform> transform = new osg::MatrixTransform;
    osg::ref_ptr<osg::Geometry> geometry;
    osg::ref_ptr<osg::StateSet> state = new osg::StateSet;
    osg::Vec3d boxSize;
    unsigned int lastCull = 0;
};

ScreenPasses::ScreenPasses() : _barrier(new osg::Geode)
{
    _barrier->addDrawable(new ImageBarrier);
    _barrier->setCullingActive(false);
    _barrier->getOrCreateStateSet()->setRenderBinDetails(9, "RenderBin");
}

ScreenPasses::~ScreenPasses() = default;

void ScreenPasses::beginCull(osgUtil::CullVisitor& cv, unsigned int cullCount)
{
    _cull = cullCount;
    _camera = cv.getCurrentCamera();
    const osg::Viewport* vp = cv.getViewport();
    _viewport = vp ? osg::Vec4i(int(vp->x()), int(vp->y()), int(vp->width()), int(vp->height())) : osg::Vec4i(0, 0, 1, 1);
    // A stamp per cull, exact in float (24-bit mantissa) and never 0 (fresh images hold 0).
    if (const osg::FrameStamp* fs = cv.getFrameStamp()) _frameStamp = float(fs->getFrameNumber() % (1u << 23) + 1);
}

osg::StateSet* ScreenPasses::depthState(osgUtil::CullVisitor& cv, int unit)
{
    Capture& c = _captures[_camera];
    if (c.geode->getNumDrawables() == 0) {
        c.geode->addDrawable(new DepthCopy(c.texture.get()));
        c.geode->setCullingActive(false);
        c.geode->getOrCreateStateSet()->setRenderBinDetails(5, "RenderBin");
    }
    fit(*c.texture, _viewport.z(), _viewport.w());
    c.origin->set(osg::Vec2f(float(_viewport.x()), float(_viewport.y())));
    c.lastCull = _cull;
    if (c.scheduled != _cull) {  // once per camera and frame, whatever the number of volumes
        c.scheduled = _cull;
        c.geode->accept(cv);
    }
    osg::ref_ptr<osg::StateSet>& ss = c.stateByUnit[unit];
    if (!ss) {
        ss = new osg::StateSet;
        ss->setTextureAttribute(unit, c.texture.get(), osg::StateAttribute::ON);
        ss->addUniform(new osg::Uniform("volren_depthTexture", unit));
        ss->addUniform(c.origin.get());
    }
    return ss.get();
}

osg::StateSet* ScreenPasses::entryState(osgUtil::CullVisitor& cv, const void* key, osg::Geometry& box,
                                        const osg::Vec3d& boxSize, const osg::Matrix& matrix)
{
    if (!_entryProgram) {
        _entryProgram = new osg::Program;
        _entryProgram->setName("volren entry points");
        _entryProgram->addShader(new osg::Shader(osg::Shader::VERTEX, ShaderFunctionRegistry::instance().read("RaySetup/box.vert")));
        _entryProgram->addShader(new osg::Shader(osg::Shader::FRAGMENT, ShaderFunctionRegistry::instance().read("RaySetup/rasterised_entry.frag")));
    }
    Entry& e = _entries[{_camera, key}];
    if (!e.geometry || e.geometry->getVertexArray() != box.getVertexArray() || e.boxSize != boxSize ||
        e.geometry->getUseVertexArrayObject() != box.getUseVertexArrayObject()) {
        e.geometry = new osg::Geometry(box, osg::CopyOp::SHALLOW_COPY);  // same vertices and faces
        e.boxSize = boxSize;
        osg::ref_ptr<osg::StateSet> faces = new osg::StateSet;  // front faces, no colour or depth
        faces->setAttributeAndModes(_entryProgram.get(), osg::StateAttribute::ON);
        faces->setAttributeAndModes(new osg::CullFace(osg::CullFace::BACK), osg::StateAttribute::ON);
        faces->setAttributeAndModes(new osg::ColorMask(false, false, false, false), osg::StateAttribute::ON);
        faces->setAttributeAndModes(new osg::Depth(osg::Depth::ALWAYS, 0.0, 1.0, false), osg::StateAttribute::ON);
        faces->setMode(GL_DEPTH_TEST, osg::StateAttribute::OFF);
        faces->addUniform(new osg::Uniform("volren_worldSize", osg::Vec3f(boxSize)));
        faces->setRenderBinDetails(8, "RenderBin");
        e.geometry->setStateSet(faces.get());
        osg::ref_ptr<osg::Geode> geode = new osg::Geode;
        geode->addDrawable(e.geometry.get());
        e.transform->removeChildren(0, e.transform->getNumChildren());
        e.transform->addChild(geode.get());
        e.state->setAttribute(new osg::BindImageTexture(0, e.texture.get(), osg::BindImageTexture::READ_WRITE, GL_RGBA32F_ARB));
    }
    fit(*e.texture, _viewport.z(), _viewport.w());
    e.state->getOrCreateUniform("volren_viewportOrigin", osg::Uniform::FLOAT_VEC2)
        ->set(osg::Vec2f(float(_viewport.x()), float(_viewport.y())));
    e.state->getOrCreateUniform("volren_frameStamp", osg::Uniform::FLOAT)->set(_frameStamp);
    e.lastCull = _cull;
    e.transform->setMatrix(matrix);
    cv.pushStateSet(e.state.get());
    e.transform->accept(cv);
    cv.popStateSet();
    if (_barrierScheduled != _cull) {  // one barrier after all entry passes of this camera
        _barrierScheduled = _cull;
        _barrier->accept(cv);
    }
    return e.state.get();
}

void ScreenPasses::endCull(unsigned int cullCount)
{
    auto stale = [cullCount](unsigned int last) { return cullCount - last > 2; };
    for (auto it = _captures.begin(); it != _captures.end();) it = stale(it->second.lastCull) ? _captures.erase(it) : std::next(it);
    for (auto it = _entries.begin(); it != _entries.end();) it = stale(it->second.lastCull) ? _entries.erase(it) : std::next(it);
}

std::size_t ScreenPasses::textureCount() const
{
    return _captures.size() + _entries.size();
}

std::size_t ScreenPasses::textureBytes() const
{
    std::size_t bytes = 0;
    for (const auto& [camera, c] : _captures)
        bytes += std::size_t(c.texture->getTextureWidth()) * std::size_t(c.texture->getTextureHeight()) * 4;
    for (const auto& [key, e] : _entries)
        bytes += std::size_t(e.texture->getTextureWidth()) * std::size_t(e.texture->getTextureHeight()) * 16;
    return bytes;
}

}  // namespace volren
