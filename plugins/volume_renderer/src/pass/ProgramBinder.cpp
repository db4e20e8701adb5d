#include "ProgramBinder.h"

#include "../compositor/BuildSlots.h"

#include <volume_renderer/GraphicsDriver.h>
#include <volume_renderer/LoopBudget.h>
#include <volume_renderer/SampleDistance.h>
#include <volume_renderer/VolumeMipChain.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>
#include <string>

namespace volren {

BindContext bindContextFor(const VolumeCandidate& candidate, osg::StateSet& stateSet, const ComposedProgram& program)
{
    const VolumeNode& node = *candidate.node;
    BindContext context{.node = node,
                       .volume = *node.getVolume(),
                       .transfer = *node.getTransferFunction(),
                       .settings = node.settings,
                       .sampleDistance = std::ldexp(effectiveSampleDistance(node), candidate.lod),
                       .lod = candidate.lod,
                       .coarseByteFiltering = candidate.coarseByteFiltering,
                       .stateSet = stateSet,
                       .textureUnits = program.textureUnits,
                       .textureToClip = candidate.textureToClip,
                       .boxSize = node.getVolume()->worldSize()};
    context.geometryShadowMatrices = candidate.geometryShadowMatrices;
    if (candidate.geometryShadowMap)  // the pass drew the opaque geometry from the lights for it
        for (const Binding& b : program.bindings)
            for (const AuxKind* kind : b.kinds)
                if (kind->scope == AuxScope::GeometryFromLights) context.aux[kind->name] = candidate.geometryShadowMap;
    return context;
}

namespace {

/// Everything a built volume of `kind` reads, as bytes compared with the last build's: the
/// build program, the volume's and the TF's identity and modified counts, the level, resident
/// bricks, the lights where the kind reads them, and the values of the uniforms and the
/// textures of the implementations its program composes (storage, reconstruction,
/// classification, clip shapes, weighting, and the implementations that need the kind) but its
/// own sampler.
std::string builtVolumeKey(const BindContext& context, const std::vector<const Binding*>& bindings, const AuxKind& kind,
                           const osg::Program* program)
{
    std::set<std::string> read = buildSamplingSlots();
    for (const Binding* b : bindings)
        if (std::find(b->kinds.begin(), b->kinds.end(), &kind) != b->kinds.end()) read.insert(b->function->slot);
    const AuxBuild& build = *kind.build;
    std::string key;
    key.reserve(256);
    auto put = [&key](const auto& value) { key.append(reinterpret_cast<const char*>(&value), sizeof(value)); };
    auto putArray = [&key](const osg::Array* a) {
        if (a) key.append(static_cast<const char*>(a->getDataPointer()), a->getTotalDataSize());
    };
    put(program);
    put(&context.volume);
    put(context.volume.modifiedCount());
    put(&context.transfer);
    put(context.transfer.modifiedCount());
    put(context.lod);
    if (context.bricks && context.bricks->pageTable->getImage())  // bricks became resident
        put(context.bricks->pageTable->getImage()->getModifiedCount());
    if (build.readsLights)
        for (const LightInfo& light : context.lights) put(light.position);
    for (const Binding* b : bindings) {
        if (!read.count(b->function->slot)) continue;
        for (const UniformDecl& u : b->function->uniforms) {
            const std::string name = (u.shared ? u.name : u.name + b->suffix) + b->memberSuffix;
            const osg::Uniform* uniform = context.stateSet.getUniform(name);
            if (!uniform || u.rayCasterOnly || (u.perLight && !build.readsLights)) continue;
            putArray(uniform->getFloatArray());
            putArray(uniform->getDoubleArray());
            putArray(uniform->getIntArray());
            putArray(uniform->getUIntArray());
        }
        for (const TextureDecl& t : b->function->textures) {
            const std::string name = (t.shared ? t.name : t.name + b->suffix) + b->memberSuffix;
            auto unit = context.textureUnits.find(name);
            if (unit == context.textureUnits.end() || name.rfind(build.sampler, 0) == 0 || t.rayCasterOnly)
                continue;  // what is built, and what only the ray caster reads
            put(context.stateSet.getTextureAttribute(unsigned(unit->second), osg::StateAttribute::TEXTURE));
        }
    }
    return key;
}

}  // namespace

bool bindProgram(BindContext& context, const ComposedProgram& program,
                 const std::map<std::string, std::vector<ClipInfo>>& clips, int member, TextureCache& textures,
                 unsigned int cull)
{
    std::vector<const Binding*> mine;
    for (const Binding& b : program.bindings)
        if (b.member == member) mine.push_back(&b);
    // The kinds of auxiliary data they need, once each, in the order the kinds ask for.
    std::vector<const AuxKind*> kinds;
    for (const Binding* b : mine)
        for (const AuxKind* kind : b->kinds)
            if (kind->scope == AuxScope::Volume && std::find(kinds.begin(), kinds.end(), kind) == kinds.end())
                kinds.push_back(kind);
    std::stable_sort(kinds.begin(), kinds.end(), [](const AuxKind* a, const AuxKind* b) { return a->order < b->order; });
    for (const Binding* b : mine)
        if (b->instance < 0) context.chosen[b->function->slot] = b->function->name;
    context.volumeTexture = [&textures, cull](const Volume& v, bool nearest) { return textures.volume(v, nearest, cull); };
    bool anyVisible = true;
    AuxRequest request{.context = context, .bindings = mine, .textures = textures, .cull = cull, .anyVisible = anyVisible};
    for (const AuxKind* kind : kinds) {
        if (kind->provide) {
            context.aux[kind->name] = kind->provide(request);
            continue;
        }
        const AuxBuild& build = *kind->build;
        const osg::Vec3i levelDims = mipDims(context.volume.dims(), context.lod);
        const osg::Vec3i dims = build.dims(levelDims, context);
        if (exceedsLargest3DTexture(dims))  // the driver would refuse its storage with a GL error
            throw std::runtime_error(kind->name + ": volume '" + context.node.getName() + "' needs " + std::to_string(dims.x()) +
                                     "x" + std::to_string(dims.y()) + "x" + std::to_string(dims.z()) +
                                     " texels, beyond this driver's largest 3D texture (" +
                                     std::to_string(largest3DTexture()) + "): choose another implementation or a coarser level");
        context.aux[kind->name] = textures.builtVolumes().texture(&context.node, *kind, dims, build.channels(context), cull);
    }

    checkViewRayWithinLoopLimit(context);  // the step is final: a brick pool may have coarsened it
    static const std::vector<ClipInfo> none;
    for (const Binding* b : mine) {
        if (!b->function->bind) continue;
        context.suffix = b->suffix;
        context.instance = b->instance;
        auto it = clips.find(b->function->slot);
        context.clips = it == clips.end() ? none : it->second;
        b->function->bind(context);
    }
    context.suffix.clear();
    context.instance = -1;
    // A built volume is rebuilt, before the ray caster draws, when what its build reads changed.
    if (const BuildProgram* buildProgram = program.build(member)) {
        const osg::Vec3d box = context.boxSize.length2() > 0.0 ? context.boxSize : context.volume.worldSize();
        for (const AuxKind* kind : kinds) {
            if (!kind->build) continue;
            const osg::Texture3D& t = static_cast<const osg::Texture3D&>(*context.aux.at(kind->name));
            const osg::Vec3i dims(t.getTextureWidth(), t.getTextureHeight(), t.getTextureDepth());
            if (osg::Node* build = textures.builtVolumes().build(&context.node, kind->name,
                                                                 builtVolumeKey(context, mine, *kind, buildProgram->program.get()),
                                                                 buildProgram->program.get(), kind->build->plan(context, box, dims)))
                context.prepasses.push_back(build);
        }
    }
    return anyVisible;
}

}  // namespace volren

namespace volren {

const ShaderFunction* AuxRequest::chosen(const std::string& slot) const
{
    for (const Binding* b : bindings)
        if (b->function->slot == slot) return b->function;
    return nullptr;
}

}  // namespace volren
