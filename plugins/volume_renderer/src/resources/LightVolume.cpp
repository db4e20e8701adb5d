// Propagated light volumes: a half-float 3D texture per VolumeNode holding each light's
// transmittance, written slice by slice by a compute program (Shadowing/light_volume_build.comp)
// swept along the axis most aligned with the light, nearest the light first.
#include "LightVolume.h"

#include <volume_model/VolumeNode.h>

#include <osg/BindImageTexture>
#include <osg/Drawable>
#include <osg/GLExtensions>
#include <osg/Geode>
#include <osg/Notify>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>

#ifndef GL_SHADER_IMAGE_ACCESS_BARRIER_BIT
#define GL_SHADER_IMAGE_ACCESS_BARRIER_BIT 0x00000020
#endif
#ifndef GL_TEXTURE_FETCH_BARRIER_BIT
#define GL_TEXTURE_FETCH_BARRIER_BIT 0x00000008
#endif

namespace volren {

namespace {

constexpr int maxChannels = 4;
constexpr int groupSize = 8;  // local_size_x and _y of the build shader

/// One light's sweep: the axis and the slices in the order they are built.
struct Sweep
{
    int light = 0;
    int axis = 2;
    std::vector<int> slices;
};

/// The sweep of a light at `light` (local coordinates, w = 0: direction towards it) over a box of
/// `worldSize` with `dims` texels: along the axis where the light's direction advances most in
/// texels, each slice after its neighbour towards the light.
Sweep sweepFor(int index, const osg::Vec4d& light, const osg::Vec3d& worldSize, const osg::Vec3i& dims)
{
    Sweep s;
    s.light = index;
    // Where the light is in texture space (a point light) or where it comes from (directional).
    osg::Vec3d towards;
    osg::Vec3d lightTex;
    for (int a = 0; a < 3; ++a) {
        lightTex[a] = light[a] / worldSize[a] + 0.5;
        towards[a] = light.w() == 0.0 ? light[a] / worldSize[a] : lightTex[a] - 0.5;
    }
    double best = -1.0;
    for (int a = 0; a < 3; ++a)
        if (const double advance = std::abs(towards[a]) * dims[a]; advance > best) best = advance, s.axis = a;
    const int n = dims[s.axis];
    s.slices.resize(std::size_t(n));
    std::iota(s.slices.begin(), s.slices.end(), 0);
    if (light.w() == 0.0) {
        if (towards[s.axis] > 0.0) std::reverse(s.slices.begin(), s.slices.end());
    } else {
        const double c = lightTex[s.axis];
        std::stable_sort(s.slices.begin(), s.slices.end(), [&](int a, int b) {
            return std::abs((a + 0.5) / n - c) < std::abs((b + 0.5) / n - c);
        });
    }
    return s;
}

/// Runs the sweeps of one build with the program OSG applied for it, once per change of key.
class LightVolumeBuild : public osg::Drawable
{
public:
    LightVolumeBuild()
    {
        setCullingActive(false);
        setUseDisplayList(false);
        setDataVariance(osg::Object::DYNAMIC);  // the next frame's cull waits for its draw
    }
    LightVolumeBuild(const LightVolumeBuild& other, const osg::CopyOp& op) : osg::Drawable(other, op) {}
    META_Object(volren, LightVolumeBuild)

    /// What the next draw builds: `key` over a volume of `dims` texels.
    void schedule(const std::string& key, const osg::Vec3i& dims, std::vector<Sweep> sweeps)
    {
        _key = key;
        _dims = dims;
        _sweeps = std::move(sweeps);
    }
    const std::string& builtKey() const { return _built; }
    unsigned int builds() const { return _builds; }
    double lastSeconds() const { return _seconds; }

    void drawImplementation(osg::RenderInfo& info) const override
    {
        if (_built == _key) return;  // drawn again (another camera) after the build
        osg::State& state = *info.getState();
        const osg::GLExtensions* ext = state.get<osg::GLExtensions>();
        const osg::Program::PerContextProgram* pcp = state.getLastAppliedProgramObject();
        if (!ext || !ext->glDispatchCompute || !ext->glMemoryBarrier || !pcp) {
            if (!_warned) OSG_WARN << "volren: this GL context cannot run compute shaders: light volume left unlit" << std::endl;
            _warned = true;
            return;
        }
        const GLint lightLocation = pcp->getUniformLocation(osg::Uniform::getNameID("volren_buildLight"));
        const GLint axisLocation = pcp->getUniformLocation(osg::Uniform::getNameID("volren_buildAxis"));
        const GLint sliceLocation = pcp->getUniformLocation(osg::Uniform::getNameID("volren_buildSlice"));
        glFinish();  // the build's own time, not what was queued before it
        const auto start = std::chrono::steady_clock::now();
        for (const Sweep& s : _sweeps) {
            const int u = s.axis == 0 ? 1 : 0, v = s.axis == 2 ? 1 : 2;
            const GLuint gx = GLuint((_dims[u] + groupSize - 1) / groupSize), gy = GLuint((_dims[v] + groupSize - 1) / groupSize);
            ext->glUniform1i(lightLocation, s.light);
            ext->glUniform1i(axisLocation, s.axis);
            for (int slice : s.slices) {
                ext->glUniform1i(sliceLocation, slice);
                ext->glDispatchCompute(gx, gy, 1);
                ext->glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
            }
        }
        ext->glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
        glFinish();
        _seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        _built = _key;
        ++_builds;
    }

private:
    std::string _key;
    osg::Vec3i _dims;
    std::vector<Sweep> _sweeps;
    mutable std::string _built;
    mutable unsigned int _builds = 0;
    mutable double _seconds = 0.0;
    mutable bool _warned = false;
};

}  // namespace

struct LightVolumes::Entry
{
    std::string name;
    osg::ref_ptr<osg::Texture3D> texture;
    int channels = 0;
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    osg::ref_ptr<LightVolumeBuild> build = new LightVolumeBuild;
    osg::ref_ptr<osg::StateSet> state = new osg::StateSet;
    osg::ref_ptr<osg::Program> program;
    unsigned int lastCull = 0;
};

osg::Vec3i lightVolumeDims(const osg::Vec3i& dims, double scale)
{
    osg::Vec3i out;
    for (int a = 0; a < 3; ++a) out[a] = std::max(2, int(std::lround(dims[a] * std::clamp(scale, 1e-3, 1.0))));
    return out;
}

LightVolumes::LightVolumes() = default;
LightVolumes::~LightVolumes() = default;

osg::Texture3D* LightVolumes::texture(const VolumeNode* node, const osg::Vec3i& dims, int lights, unsigned int cull)
{
    std::unique_ptr<Entry>& e = _entries[node];
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
    e->lastCull = cull;
    const int channels = std::clamp(lights, 1, maxChannels) == 3 ? 4 : std::clamp(lights, 1, maxChannels);
    osg::Texture3D* t = e->texture.get();
    if (!t || t->getTextureWidth() != dims.x() || t->getTextureHeight() != dims.y() || t->getTextureDepth() != dims.z() ||
        e->channels != channels) {
        static const GLint formats[] = {0, GL_R16F, GL_RG16F, 0, GL_RGBA16F_ARB};
        static const GLenum sources[] = {0, GL_RED, GL_RG, 0, GL_RGBA};
        e->texture = t = new osg::Texture3D;
        t->setTextureSize(dims.x(), dims.y(), dims.z());
        t->setInternalFormat(formats[channels]);
        t->setSourceFormat(sources[channels]);
        t->setSourceType(GL_HALF_FLOAT);
        for (auto w : {osg::Texture::WRAP_S, osg::Texture::WRAP_T, osg::Texture::WRAP_R})
            t->setWrap(w, osg::Texture::CLAMP_TO_EDGE);
        t->setFilter(osg::Texture::MIN_FILTER, osg::Texture::LINEAR);
        t->setFilter(osg::Texture::MAG_FILTER, osg::Texture::LINEAR);
        t->setResizeNonPowerOfTwoHint(false);
        t->setDataVariance(osg::Object::DYNAMIC);
        e->channels = channels;
        e->state->setAttribute(new osg::BindImageTexture(1, t, osg::BindImageTexture::READ_WRITE, GLenum(formats[channels]),
                                                         0, GL_TRUE));
        e->build->schedule("", dims, {});  // nothing built into the new texture yet
    }
    return t;
}

osg::Node* LightVolumes::build(const VolumeNode* node, const std::string& key, osg::Program* program,
                               const std::vector<LightInfo>& lights, const osg::Vec3d& worldSize)
{
    Entry& e = *_entries.at(node);
    if (e.program != program) {
        e.state->setAttributeAndModes(program, osg::StateAttribute::ON);
        e.program = program;
    }
    const std::string full = key + " " + std::to_string(reinterpret_cast<std::uintptr_t>(e.texture.get()));
    if (e.build->builtKey() == full) return nullptr;
    const osg::Vec3i dims(e.texture->getTextureWidth(), e.texture->getTextureHeight(), e.texture->getTextureDepth());
    std::vector<Sweep> sweeps;
    for (std::size_t i = 0; i < lights.size() && i < std::size_t(maxChannels); ++i)
        sweeps.push_back(sweepFor(int(i), lights[i].position, worldSize, dims));
    e.build->schedule(full, dims, std::move(sweeps));
    return e.geode.get();
}

void LightVolumes::endCull(unsigned int cull)
{
    for (auto it = _entries.begin(); it != _entries.end();)
        it = cull - it->second->lastCull > 2 ? _entries.erase(it) : std::next(it);
}

std::size_t LightVolumes::bytes() const
{
    std::size_t total = 0;
    for (const auto& [node, e] : _entries)
        if (e->texture)
            total += std::size_t(e->texture->getTextureWidth()) * e->texture->getTextureHeight() *
                     e->texture->getTextureDepth() * 2 * std::size_t(e->channels);
    return total;
}

std::vector<LightVolumeStatistics> LightVolumes::statistics(unsigned int cull) const
{
    std::vector<LightVolumeStatistics> out;
    for (const auto& [node, e] : _entries) {
        if (e->lastCull != cull || !e->texture) continue;
        const osg::Vec3i dims(e->texture->getTextureWidth(), e->texture->getTextureHeight(), e->texture->getTextureDepth());
        out.push_back({e->name, dims, e->channels, std::size_t(dims.x()) * dims.y() * dims.z() * 2 * std::size_t(e->channels),
                       e->build->builds(), e->build->lastSeconds()});
    }
    return out;
}

}  // namespace volren
