#include "ProgramBinder.h"

#include "../compositor/BuildSlots.h"
#include "../resources/BuiltVolumeKinds.h"

#include <volume_renderer/GraphicsDriver.h>
#include <volume_renderer/SampleDistance.h>

#include <volume_renderer/VolumeMipChain.h>

#include <cmath>
#include <cstdio>
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
    if (candidate.geometryShadowMap) context.aux[AuxData::GeometryShadowMap] = candidate.geometryShadowMap;
    return context;
}

namespace {

/// The bound Reconstruction's footprint: the apron of the macrocell value ranges.
int footprintOf(const std::vector<const Binding*>& bindings)
{
    for (const Binding* b : bindings)
        if (b->function->slot == "Reconstruction" && b->function->traits.footprint >= 0) return b->function->traits.footprint;
    throw std::logic_error("macrocell grid without a Reconstruction footprint");  // the policy's rules exclude this
}

/// The occupancy grid of the bound volume under the bound Classification's opacity mirror; with
/// `homogeneity`, visible cells tell whether the classification varies within adaptiveTolerance
/// there (none is homogeneous for a Classification without a variation mirror or a volume with
/// NaN voxels, whose interpolated samples turn transparent).
osg::Texture* occupancyFor(const BindContext& context, const std::vector<const Binding*>& bindings,
                           TextureCache& textures, unsigned int cull, bool homogeneity, bool& anyVisible)
{
    const ShaderFunction* classification = nullptr;
    for (const Binding* b : bindings)
        if (b->function->slot == "Classification") classification = b->function;
    const int footprint = footprintOf(bindings);
    if (!classification || !classification->mayShow)  // the policy's rules exclude this
        throw std::logic_error("occupancy grid without a Classification mirror");
    // What the classification's opacity depends on besides the volume and the TF.
    char key[96];
    std::snprintf(key, sizeof(key), " %a", context.settings.number("threshold"));  // exact
    std::string fullKey = classification->name + key;
    const bool varies = homogeneity && classification->variation && context.volume.nonFiniteCount() == 0;
    if (homogeneity) {
        std::snprintf(key, sizeof(key), " homogeneous within %a", varies ? context.settings.number("adaptiveTolerance") : -1.0);
        fullKey += key;
    }
    const GridShape shape = gridShapeFor(context.volume.dims(), context.settings.macrocellSize, footprint, context.lod);
    return textures.occupancy(
        context.volume, context.transfer, shape.cellSize, shape.apron, fullKey,
        [&]() -> std::pair<TextureCache::CellTest, TextureCache::CellTest> {
            TextureCache::CellTest homogeneous;
            if (varies)
                homogeneous = [variation = classification->variation(context),
                               tolerance = context.settings.number("adaptiveTolerance")](double lo, double hi) {
                    return variation(lo, hi) <= tolerance;
                };
            else if (homogeneity)
                homogeneous = [](double, double) { return false; };
            return {classification->mayShow(context), homogeneous};
        },
        cull, anyVisible);
}

/// Which bricks the bound transfer function hides, where the traversal leaps over transparent
/// space (as empty-space skipping by default): the Classification's opacity mirror over each
/// brick's values with the Reconstruction's footprint and the gradient's one voxel around it.
/// Null for MIP, isosurfaces, classifications without a mirror and coarse previews.
std::optional<BrickHidingRule> hidingFor(const BindContext& context, const std::vector<const Binding*>& bindings)
{
    const ShaderFunction *traversal = nullptr, *classification = nullptr, *reconstruction = nullptr;
    for (const Binding* b : bindings) {
        if (b->function->slot == "RayTraversal") traversal = b->function;
        if (b->function->slot == "Classification") classification = b->function;
        if (b->function->slot == "Reconstruction") reconstruction = b->function;
    }
    if (!traversal || !classification || !reconstruction || !classification->mayShow || reconstruction->traits.footprint < 0 ||
        traversal->traits.skips != "opacity" || !traversal->traits.skipsByDefault)
        return std::nullopt;
    char key[160];
    std::snprintf(key, sizeof(key), " %a %p %u", context.settings.number("threshold"), static_cast<const void*>(&context.transfer),
                  context.transfer.modifiedCount());
    return BrickHidingRule{.apron = reconstruction->traits.footprint + 1,
                           .key = classification->name + key,
                           .mayShow = classification->mayShow(context)};
}

/// Everything a built volume of `kind` reads, as bytes compared with the last build's: the
/// build program, the volume's and the TF's identity and modified counts, the level, resident
/// bricks, the lights where the kind reads them, and the values of the uniforms and the
/// textures of the implementations its program composes (storage, reconstruction,
/// classification, clip shapes, weighting, shadowing) but its own.
std::string builtVolumeKey(const BindContext& context, const std::vector<const Binding*>& bindings,
                           const BuiltVolumeKind& kind, const osg::Program* program)
{
    static const std::set<std::string> read = [] {  // what the build program composes, and its own slot
        std::set<std::string> slots = buildSamplingSlots();
        slots.insert("Shadowing");
        return slots;
    }();
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
    if (kind.readsLights)
        for (const LightInfo& light : context.lights) put(light.position);
    for (const Binding* b : bindings) {
        if (!read.count(b->function->slot)) continue;
        for (const UniformDecl& u : b->function->uniforms) {
            const std::string name = (u.shared ? u.name : u.name + b->suffix) + b->memberSuffix;
            const osg::Uniform* uniform = context.stateSet.getUniform(name);
            if (!uniform || u.rayCasterOnly || (!kind.readsLights && name.rfind("volren_light", 0) == 0)) continue;
            putArray(uniform->getFloatArray());
            putArray(uniform->getDoubleArray());
            putArray(uniform->getIntArray());
            putArray(uniform->getUIntArray());
        }
        for (const TextureDecl& t : b->function->textures) {
            const std::string name = (t.shared ? t.name : t.name + b->suffix) + b->memberSuffix;
            auto unit = context.textureUnits.find(name);
            if (unit == context.textureUnits.end() || name.rfind(kind.sampler, 0) == 0 || t.rayCasterOnly)
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
    auto needs = [&](AuxData aux) {
        for (const Binding* b : mine)
            if (b->function->needsAux(aux)) return true;
        return false;
    };
    for (const Binding* b : mine)
        if (b->instance < 0) context.chosen[b->function->slot] = b->function->name;
    context.volumeTexture = [&textures, cull](const Volume& v, bool nearest) { return textures.volume(v, nearest, cull); };
    // The texture of the mip level sampled (level of detail), 16-bit where texturePrecision says.
    const std::string& precision = context.settings.texturePrecision;
    const bool wide = precision == "16bit" || (precision == "auto" && context.coarseByteFiltering);
    if (needs(AuxData::VolumeTexture))
        context.aux[AuxData::VolumeTexture] = textures.volume(context.volume, false, cull, context.lod, wide);
    if (needs(AuxData::BrickPool)) {
        const std::optional<BrickHidingRule> hiding = hidingFor(context, mine);
        const BrickedVolume& bricks =
            textures.bricked(context.volume, context.lod, context.settings.brickSize, volumeMemoryBudget(context.settings),
                             largest3DTexture(), wide, context.textureToClip, hiding ? &*hiding : nullptr, cull);
        context.bricks = &bricks;
        context.aux[AuxData::BrickPool] = bricks.pool;
        // The budget holds the levels from levelSampled down: the volume is sampled there, at
        // that level's step, as if it were the node's level of detail.
        if (const int level = bricks.levelSampled; level > context.lod) {
            context.sampleDistance = std::ldexp(context.sampleDistance, level - context.lod);
            context.lod = level;
        }
    }
    if (needs(AuxData::TransferFunctionTable))
        context.aux[AuxData::TransferFunctionTable] = textures.table(context.transfer, false, cull);
    if (needs(AuxData::PremultipliedTable))
        context.aux[AuxData::PremultipliedTable] = textures.table(context.transfer, true, cull);
    bool anyVisible = true;
    if (needs(AuxData::OccupancyGrid))
        context.aux[AuxData::OccupancyGrid] = occupancyFor(context, mine, textures, cull, false, anyVisible);
    if (needs(AuxData::HomogeneityGrid))
        context.aux[AuxData::HomogeneityGrid] = occupancyFor(context, mine, textures, cull, true, anyVisible);
    if (needs(AuxData::MacrocellRanges)) {
        const GridShape shape =
            gridShapeFor(context.volume.dims(), context.settings.macrocellSize, footprintOf(mine), context.lod);
        context.aux[AuxData::MacrocellRanges] = textures.ranges(context.volume, shape.cellSize, shape.apron, cull);
    }
    const osg::Vec3i levelDims = mipDims(context.volume.dims(), context.lod);
    for (const BuiltVolumeKind& kind : builtVolumeKinds())
        if (needs(kind.aux))
            context.aux[kind.aux] = textures.builtVolumes().texture(&context.node, kind.aux, kind.dims(levelDims, context),
                                                                    kind.channels(context), kind.mipmapped, cull);

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
        for (const BuiltVolumeKind& kind : builtVolumeKinds()) {
            if (!needs(kind.aux)) continue;
            const osg::Texture3D& t = static_cast<const osg::Texture3D&>(*context.aux.at(kind.aux));
            const osg::Vec3i dims(t.getTextureWidth(), t.getTextureHeight(), t.getTextureDepth());
            if (osg::Node* build = textures.builtVolumes().build(&context.node, kind.aux,
                                                                 builtVolumeKey(context, mine, kind, buildProgram->program.get()),
                                                                 buildProgram->program.get(), kind.plan(context, box, dims)))
                context.prepasses.push_back(build);
        }
    }
    return anyVisible;
}

}  // namespace volren
