// Auxiliary volumes built on the GPU: a half-float 3D texture per node and kind, written by a
// composition's compute program in the dispatches its plan lists (mip levels too: the driver's
// mipmap generation may blend the zero border into edge texels, so the plan writes them).
#include "BuiltVolumes.h"

#include <volume_model/Volume.h>
#include <volume_model/VolumeNode.h>

#include <osg/BindImageTexture>
#include <osg/Drawable>
#include <osg/GLExtensions>
#include <osg/Geode>
#include <osg/Notify>

#include <algorithm>
#include <chrono>
#include <set>

#ifndef GL_SHADER_IMAGE_ACCESS_BARRIER_BIT
#define GL_SHADER_IMAGE_ACCESS_BARRIER_BIT 0x00000020
#endif
#ifndef GL_TEXTURE_FETCH_BARRIER_BIT
#define GL_TEXTURE_FETCH_BARRIER_BIT 0x00000008
#endif

namespace volren {

namespace {

/// Runs a build's plan with the program OSG applied for it, once per change of key.
class VolumeBuild : public osg::Drawable
{
public:
    VolumeBuild()
    {
        setCullingActive(false);
        setUseDisplayList(false);
        setDataVariance(osg::Object::DYNAMIC);  // the next frame's cull waits for its draw
    }
    VolumeBuild(const VolumeBuild& other, const osg::CopyOp& op) : osg::Drawable(other, op) {}
    META_Object(volren, VolumeBuild)

    /// What the next draw builds into `texture` (its levels allocated first when `mipmaps`):
    /// `key`, by `plan`.
    void schedule(const std::string& key, osg::Texture3D* texture, std::vector<BuildDispatch> plan, bool mipmaps)
    {
        if (_texture != texture) _allocated.clear();
        _key = key;
        _texture = texture;
        _plan = std::move(plan);
        _mipmaps = mipmaps;
    }
    const std::string& builtKey() const { return _built; }
    unsigned int builds() const { return _builds; }
    double lastSeconds() const { return _seconds; }

    void drawImplementation(osg::RenderInfo& info) const override
    {
        if (_built == _key || !_texture) return;  // drawn again (another camera) after the build
        osg::State& state = *info.getState();
        const osg::GLExtensions* ext = state.get<osg::GLExtensions>();
        const osg::Program::PerContextProgram* pcp = state.getLastAppliedProgramObject();
        if (!ext || !ext->glDispatchCompute || !ext->glMemoryBarrier || !pcp) {
            if (!_warned) OSG_WARN << "volren: this GL context cannot run compute shaders: auxiliary volume left empty" << std::endl;
            _warned = true;
            return;
        }
        glFinish();  // the build's own time, not what was queued before it
        const auto start = std::chrono::steady_clock::now();
        const unsigned int context = state.getContextID();
        if (_mipmaps && ext->glGenerateMipmap && !_allocated.count(context)) {
            // Storage for every level (their contents are the plan's to write), through unit 0,
            // which then gets back the texture the build's samplers expect there.
            const osg::StateAttribute* previous = state.getLastAppliedTextureAttribute(0, osg::StateAttribute::TEXTURE);
            state.applyTextureAttribute(0, _texture.get());
            ext->glGenerateMipmap(GL_TEXTURE_3D);
            if (previous) state.applyTextureAttribute(0, previous);
            _allocated.insert(context);
        }
        const osg::Texture::TextureObject* object = _texture->getTextureObject(context);
        const GLenum format = GLenum(_texture->getInternalFormat());
        for (const BuildDispatch& d : _plan) {
            if (d.level > 0 && object) {
                ext->glBindImageTexture(1, object->id(), d.level, GL_TRUE, 0, GL_READ_WRITE, format);
                ext->glBindImageTexture(2, object->id(), d.level - 1, GL_TRUE, 0, GL_READ_ONLY, format);
            }
            for (const auto& [name, value] : d.uniforms)
                ext->glUniform1i(pcp->getUniformLocation(osg::Uniform::getNameID(name)), value);
            ext->glDispatchCompute(GLuint(d.groups.x()), GLuint(d.groups.y()), GLuint(d.groups.z()));
            ext->glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
        }
        if (object)  // unit 1 back at level 0, as OSG's BindImageTexture left it
            ext->glBindImageTexture(1, object->id(), 0, GL_TRUE, 0, GL_READ_WRITE, format);
        ext->glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
        glFinish();
        _seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        _built = _key;
        ++_builds;
    }

private:
    std::string _key;
    osg::ref_ptr<osg::Texture3D> _texture;
    std::vector<BuildDispatch> _plan;
    bool _mipmaps = false;
    mutable std::string _built;
    mutable unsigned int _builds = 0;
    mutable double _seconds = 0.0;
    mutable bool _warned = false;
    mutable std::set<unsigned int> _allocated;  ///< contexts where the levels have storage
};

}  // namespace

struct BuiltVolumes::Entry
{
    std::string name;
    std::size_t voxels = 0;
    osg::ref_ptr<osg::Texture3D> texture;
    int channels = 0;
    bool mipmapped = false;
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    osg::ref_ptr<VolumeBuild> build = new VolumeBuild;
    osg::ref_ptr<osg::StateSet> state = new osg::StateSet;
    osg::ref_ptr<osg::Program> program;
    unsigned int lastCull = 0;

    std::size_t bytes() const
    {
        if (!texture) return 0;
        std::size_t total = 0;
        osg::Vec3i d(texture->getTextureWidth(), texture->getTextureHeight(), texture->getTextureDepth());
        for (;;) {
            total += std::size_t(d.x()) * d.y() * d.z() * 2 * std::size_t(channels);
            if (!mipmapped || (d.x() == 1 && d.y() == 1 && d.z() == 1)) break;
            d = osg::Vec3i(std::max(1, d.x() / 2), std::max(1, d.y() / 2), std::max(1, d.z() / 2));
        }
        return total;
    }
};

BuiltVolumes::BuiltVolumes() = default;
BuiltVolumes::~BuiltVolumes() = default;

osg::Texture3D* BuiltVolumes::texture(const VolumeNode* node, const AuxKind& kind, const osg::Vec3i& dims, int channels,
                                      unsigned int cull)
{
    const AuxBuild& build = *kind.build;
    const bool mipmapped = build.mipmapped;
    std::unique_ptr<Entry>& e = _entries[{node, kind.name}];
    if (!e) {
        e = std::make_unique<Entry>();
        e->geode->addDrawable(e->build.get());
        e->geode->setCullingActive(false);
        e->build->setStateSet(e->state.get());
        // Before every ray caster (bin 10), in the stage's bins rather than nested in the ray
        // caster's, whose state it is culled under.
        e->state->setRenderBinDetails(6, "RenderBin");
        e->state->setNestRenderBins(false);
        e->state->setDataVariance(osg::Object::DYNAMIC);
    }
    e->name = node->getName();
    e->voxels = node->getVolume() ? node->getVolume()->voxelCount() : 0;
    e->lastCull = cull;
    osg::Texture3D* t = e->texture.get();
    if (!t || t->getTextureWidth() != dims.x() || t->getTextureHeight() != dims.y() || t->getTextureDepth() != dims.z() ||
        e->channels != channels || e->mipmapped != mipmapped) {
        static const GLint formats[] = {0, GL_R16F, GL_RG16F, 0, GL_RGBA16F_ARB};
        static const GLenum sources[] = {0, GL_RED, GL_RG, 0, GL_RGBA};
        e->texture = t = new osg::Texture3D;
        t->setTextureSize(dims.x(), dims.y(), dims.z());
        t->setInternalFormat(formats[channels]);
        t->setSourceFormat(sources[channels]);
        t->setSourceType(GL_HALF_FLOAT);
        for (auto w : {osg::Texture::WRAP_S, osg::Texture::WRAP_T, osg::Texture::WRAP_R}) t->setWrap(w, build.wrap);
        t->setBorderColor(osg::Vec4d(0, 0, 0, 0));
        t->setFilter(osg::Texture::MIN_FILTER, build.minFilter);
        t->setFilter(osg::Texture::MAG_FILTER, osg::Texture::LINEAR);
        t->setUseHardwareMipMapGeneration(false);  // the build makes the levels
        if (mipmapped) {  // OSG samples levels up to this count only (GL_TEXTURE_MAX_LEVEL)
            unsigned int levels = 1;
            for (int largest = std::max({dims.x(), dims.y(), dims.z()}); largest > 1; largest /= 2) ++levels;
            t->setNumMipmapLevels(levels);
        }
        t->setResizeNonPowerOfTwoHint(false);
        t->setDataVariance(osg::Object::DYNAMIC);
        e->channels = channels;
        e->mipmapped = mipmapped;
        e->state->setAttribute(new osg::BindImageTexture(1, t, osg::BindImageTexture::READ_WRITE, GLenum(formats[channels]),
                                                         0, GL_TRUE));
        e->build->schedule("", t, {}, false);  // nothing built into the new texture yet
    }
    return t;
}

osg::Texture3D* BuiltVolumes::find(const VolumeNode* node, const std::string& kind) const
{
    auto it = _entries.find({node, kind});
    return it == _entries.end() ? nullptr : it->second->texture.get();
}

osg::Node* BuiltVolumes::build(const VolumeNode* node, const std::string& kind, const std::string& key, osg::Program* program,
                               std::vector<BuildDispatch> plan)
{
    Entry& e = *_entries.at({node, kind});
    if (e.program != program) {
        e.state->setAttributeAndModes(program, osg::StateAttribute::ON);
        e.program = program;
    }
    std::string full = key;  // and the texture it is built into (bytes of the pointer)
    const osg::Texture3D* texture = e.texture.get();
    full.append(reinterpret_cast<const char*>(&texture), sizeof(texture));
    if (e.build->builtKey() == full) return nullptr;
    e.build->schedule(full, e.texture.get(), std::move(plan), e.mipmapped);
    return e.geode.get();
}

void BuiltVolumes::endCull(unsigned int cull)
{
    for (auto it = _entries.begin(); it != _entries.end();)
        it = cull - it->second->lastCull > 2 ? _entries.erase(it) : std::next(it);
}

std::size_t BuiltVolumes::bytes() const
{
    std::size_t total = 0;
    for (const auto& [key, e] : _entries) total += e->bytes();
    return total;
}

std::vector<BuiltVolumeStatistics> BuiltVolumes::statistics(unsigned int cull) const
{
    std::vector<BuiltVolumeStatistics> out;
    for (const auto& [key, e] : _entries) {
        if (e->lastCull != cull || !e->texture) continue;
        const osg::Vec3i dims(e->texture->getTextureWidth(), e->texture->getTextureHeight(), e->texture->getTextureDepth());
        out.push_back({e->name, key.second, dims, e->channels, e->bytes(), e->voxels, e->build->builds(),
                       e->build->lastSeconds()});
    }
    return out;
}

}  // namespace volren
