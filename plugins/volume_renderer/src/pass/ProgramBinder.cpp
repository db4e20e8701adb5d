#include "ProgramBinder.h"

#include "../resources/LightVolume.h"
#include "../resources/OpacityMipChain.h"

#include <volume_renderer/GraphicsDriver.h>
#include <volume_renderer/SampleDistance.h>

#include <volume_renderer/VolumeMipChain.h>

#include <cmath>
#include <cstdio>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>

namespace volren {

BindContext bindContextFor(const VolumeCandidate& candidate, osg::StateSet& stateSet, const ComposedProgram& program)
{
    const VolumeNode& node = *candidate.node;
    return BindContext{.node = node,
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
    std::snprintf(key, sizeof(key), " %a", context.settings.threshold);  // exact
    std::string fullKey = classification->name + key;
    const bool varies = homogeneity && classification->variation && context.volume.nonFiniteCount() == 0;
    if (homogeneity) {
        std::snprintf(key, sizeof(key), " homogeneous within %a", varies ? context.settings.adaptiveTolerance : -1.0);
        fullKey += key;
    }
    const GridShape shape = gridShapeFor(context.volume.dims(), context.settings.macrocellSize, footprint, context.lod);
    return textures.occupancy(
        context.volume, context.transfer, shape.cellSize, shape.apron, fullKey,
        [&]() -> std::pair<TextureCache::CellTest, TextureCache::CellTest> {
            TextureCache::CellTest homogeneous;
            if (varies)
                homogeneous = [variation = classification->variation(context),
                               tolerance = context.settings.adaptiveTolerance](double lo, double hi) {
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
    std::snprintf(key, sizeof(key), " %a %p %u", context.settings.threshold, static_cast<const void*>(&context.transfer),
                  context.transfer.modifiedCount());
    return BrickHidingRule{.apron = reconstruction->traits.footprint + 1,
                           .key = classification->name + key,
                           .mayShow = classification->mayShow(context)};
}

/// Everything a built volume's build reads, as text: the values of the uniforms and the textures
/// of the implementations its program composes (storage, reconstruction, classification, clip
/// shapes, shadowing), the volume's and the TF's identity and modified counts, and the lights
/// when `lights` (a light volume; an opacity mip chain does not depend on them).
std::string builtVolumeKey(const BindContext& context, const std::vector<const Binding*>& bindings, bool lights)
{
    static const std::set<std::string> read = {"VolumeStorage", "Reconstruction", "Classification", "ClipPosition",
                                               "Shadowing"};
    std::ostringstream key;
    key << &context.volume << ' ' << context.volume.modifiedCount() << ' ' << &context.transfer << ' '
        << context.transfer.modifiedCount() << ' ' << context.lod;
    char number[40];
    auto put = [&](double v) {
        std::snprintf(number, sizeof(number), " %a", v);
        key << number;
    };
    if (context.bricks && context.bricks->pageTable->getImage())  // bricks became resident
        key << " pages " << context.bricks->pageTable->getImage()->getModifiedCount();
    if (lights)
        for (const LightInfo& light : context.lights)
            for (int i = 0; i < 4; ++i) put(light.position[i]);
    for (const Binding* b : bindings) {
        if (!read.count(b->function->slot)) continue;
        for (const UniformDecl& u : b->function->uniforms) {
            const std::string name = (u.shared ? u.name : u.name + b->suffix) + b->memberSuffix;
            const osg::Uniform* uniform = context.stateSet.getUniform(name);
            if (!uniform || (!lights && name.rfind("volren_light", 0) == 0)) continue;
            key << ' ' << name;
            if (const osg::FloatArray* a = uniform->getFloatArray())
                for (float v : *a) put(v);
            if (const osg::DoubleArray* a = uniform->getDoubleArray())
                for (double v : *a) put(v);
            if (const osg::IntArray* a = uniform->getIntArray())
                for (int v : *a) key << ' ' << v;
            if (const osg::UIntArray* a = uniform->getUIntArray())
                for (unsigned int v : *a) key << ' ' << v;
        }
        for (const TextureDecl& t : b->function->textures) {
            const std::string name = (t.shared ? t.name : t.name + b->suffix) + b->memberSuffix;
            auto unit = context.textureUnits.find(name);
            if (unit == context.textureUnits.end() || name.rfind("volren_lightVolume", 0) == 0 ||
                name.rfind("volren_opacityMips", 0) == 0)
                continue;  // what is built
            key << ' ' << name << ' ' << context.stateSet.getTextureAttribute(unsigned(unit->second), osg::StateAttribute::TEXTURE);
        }
    }
    return key.str();
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
    if (needs(AuxData::LightVolume))
        context.aux[AuxData::LightVolume] = textures.builtVolumes().texture(
            &context.node, AuxData::LightVolume, lightVolumeDims(levelDims, context.settings.lightVolumeScale),
            lightVolumeChannels(context.lights.size()), false, cull);
    if (needs(AuxData::OpacityMipChain))
        context.aux[AuxData::OpacityMipChain] =
            textures.builtVolumes().texture(&context.node, AuxData::OpacityMipChain, levelDims, 1, true, cull);

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
    if (program.buildProgram) {
        const osg::Vec3d box = context.boxSize.length2() > 0.0 ? context.boxSize : context.volume.worldSize();
        osg::Node* build = nullptr;
        if (needs(AuxData::LightVolume)) {
            const osg::Texture3D& t = static_cast<const osg::Texture3D&>(*context.aux.at(AuxData::LightVolume));
            const osg::Vec3i dims(t.getTextureWidth(), t.getTextureHeight(), t.getTextureDepth());
            build = textures.builtVolumes().build(&context.node, AuxData::LightVolume, builtVolumeKey(context, mine, true),
                                                  program.buildProgram.get(), lightVolumePlan(context.lights, box, dims));
        } else if (needs(AuxData::OpacityMipChain)) {
            build = textures.builtVolumes().build(&context.node, AuxData::OpacityMipChain,
                                                  builtVolumeKey(context, mine, false), program.buildProgram.get(),
                                                  opacityVolumePlan(levelDims));
        }
        if (build) context.prepasses.push_back(build);
    }
    return anyVisible;
}

}  // namespace volren
