// VolumeStorage implementations: where the voxels a Reconstruction reads live.
#include "CommonBindings.h"

#include "../resources/TextureCache.h"

#include <volume_renderer/BrickPool.h>
#include <volume_renderer/GraphicsDriver.h>
#include <volume_renderer/SampleDistance.h>
#include <volume_renderer/VolumeMipChain.h>
#include <volume_renderer/ShaderCompositor.h>
#include <volume_renderer/ShaderFunctionRegistry.h>

#include <volume_model/RenderSettings.h>
#include <volume_model/VolumeNode.h>
#include <volume_model/TransferFunction.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

namespace volren {

namespace {

/// Whether 8-bit data gets 16-bit texels: as texturePrecision says, or where the driver would
/// filter 8-bit texels to 8-bit results ("auto").
bool wideTexels(const BindContext& c)
{
    const std::string& precision = c.settings.texturePrecision;
    return precision == "16bit" || (precision == "auto" && c.coarseByteFiltering);
}

/// Which bricks the bound transfer function hides, where the traversal leaps over transparent
/// space (as empty-space skipping by default): the Classification's opacity mirror over each
/// brick's values with the Reconstruction's footprint and the gradient's one voxel around it.
/// Null for MIP, isosurfaces, classifications without a mirror and coarse previews.
std::optional<BrickHidingRule> hidingFor(const AuxRequest& r)
{
    const ShaderFunction* traversal = r.chosen("RayTraversal");
    const ShaderFunction* classification = r.chosen("Classification");
    const ShaderFunction* reconstruction = r.chosen("Reconstruction");
    if (!traversal || !classification || !reconstruction || !classification->mayShow || reconstruction->traits.footprint < 0 ||
        traversal->traits.skips != "opacity" || !traversal->traits.skipsByDefault)
        return std::nullopt;
    std::string key = classification->name;
    bindings::appendParameterValues(key, r.context.settings, *classification);
    bindings::appendBytes(key, &r.context.transfer);
    bindings::appendBytes(key, r.context.transfer.modifiedCount());
    return BrickHidingRule{.apron = reconstruction->traits.footprint + 1, .key = key, .mayShow = classification->mayShow(r.context)};
}

}  // namespace

void registerVolumeStorageFunctions(ShaderFunctionRegistry& registry)
{
    // The texture of the sampled mip level (TextureCache::volume), shared per volume.
    registry.addAuxKind({.name = "volume texture", .order = 0, .provide = [](AuxRequest& r) -> osg::Texture* {
                             const BindContext& c = r.context;
                             // OSG would shrink a larger image silently: a clear error instead
                             // (the policy chooses bricks for such volumes; this is a forced choice).
                             if (const osg::Vec3i d = mipDims(c.volume.dims(), c.lod); exceedsLargest3DTexture(d))
                                 throw std::runtime_error(
                                     "VolumeStorage texture: volume '" + c.node.getName() + "' is " + std::to_string(d.x()) + "x" +
                                     std::to_string(d.y()) + "x" + std::to_string(d.z()) + " texels at level " + std::to_string(c.lod) +
                                     ", beyond this driver's largest 3D texture (" + std::to_string(largest3DTexture()) +
                                     "): choose VolumeStorage bricked (--set volumeStorage=bricked)");
                             return r.textures.volume(c.volume, false, r.cull, c.lod, wideTexels(c));
                         }});
    // The volume's mip levels in bricks in a pool texture with their page table (BrickPool.h),
    // within the node's memory budget. Made first: the budget may hold only coarser levels, and
    // the volume is then sampled there, at that level's step, as if it were the node's level of
    // detail (what is shaped by the level is made after it).
    registry.addAuxKind({.name = "brick pool", .order = 0, .provide = [](AuxRequest& r) -> osg::Texture* {
                             BindContext& c = r.context;
                             const std::optional<BrickHidingRule> hiding = hidingFor(r);
                             const BrickedVolume& bricks =
                                 r.textures.bricked(c.volume, c.lod, c.settings.brickSize, volumeMemoryBudget(c.settings),
                                                    largest3DTexture(), wideTexels(c), c.textureToClip,
                                                    hiding ? &*hiding : nullptr, r.cull);
                             c.bricks = &bricks;
                             if (const int level = bricks.levelSampled; level > c.lod) {
                                 c.sampleDistance = std::ldexp(c.sampleDistance, level - c.lod);
                                 c.lod = level;
                             }
                             return bricks.pool.get();
                         }});

    registry.add({.slot = "VolumeStorage",
                  .name = "null",
                  .traits = {.calls = SlotList{}},
                  .reference = ReferenceModel::none("it reads no voxel: the sweep's 'drawn' check is its test")});
    // One 3D texture of the sampled mip level (16-bit texels of 8-bit data where texturePrecision
    // says so).
    registry.add({.slot = "VolumeStorage",
                  .name = "texture",
                  .textures = {bindings::volumeTexture},
                  .needs = {"volume texture"},
                  .bind = bindings::bindVolumeTexture,
                  .traits = {.calls = SlotList{}},
                  .reference = ReferenceModel::exact("voxel values")});
    // The levels in bricks in a pool within the node's memoryBudgetMB (BrickPool.h): chosen by the
    // policy for volumes that do not fit the budget or the largest 3D texture, or when asked.
    registry.add({.slot = "VolumeStorage",
                  .name = "bricked",
                  .uniforms = {{"volren_brickSize", "float", ""},
                               {"volren_poolSize", "vec3", ""},
                               {"volren_firstLevel", "int", ""},
                               {"volren_levelCount", "int", ""},
                               {"volren_levelDims", "vec3", "16"},
                               {"volren_brickCounts", "vec3", "16"},
                               {"volren_pageTableZ", "float", "16"}},
                  .textures = {{"volren_brickPool", "sampler3D"}, {"volren_pageTable", "sampler3D"}},
                  .needs = {"brick pool"},
                  .bind =
                      [](BindContext& c) {
                          const BrickedVolume& b = *c.bricks;
                          const BrickLayout& layout = b.layout;
                          c.texture("volren_brickPool", b.pool.get());
                          c.texture("volren_pageTable", b.pageTable.get());
                          c.uniform("volren_brickSize", float(layout.brickSize));
                          c.uniform("volren_poolSize", osg::Vec3f(float(b.poolTexels.x()), float(b.poolTexels.y()), float(b.poolTexels.z())));
                          c.uniform("volren_firstLevel", std::max(b.firstLevel, b.levelSampled));
                          c.uniform("volren_levelCount", int(layout.levels.size()));
                          for (unsigned int i = 0; i < 16; ++i) {
                              const BrickLevel level = i < layout.levels.size() ? layout.levels[i] : BrickLevel{};
                              const osg::Vec3i& d = level.dims;
                              const osg::Vec3i& n = level.bricks;
                              c.uniformElement("volren_levelDims", 16, i, osg::Vec3f(float(d.x()), float(d.y()), float(d.z())));
                              c.uniformElement("volren_brickCounts", 16, i, osg::Vec3f(float(n.x()), float(n.y()), float(n.z())));
                              c.uniformElement("volren_pageTableZ", 16, i, float(level.tableZ));
                          }
                      },
                  .traits = {.calls = SlotList{}, .withinBudget = true},
                  // At the full-resolution level; a coarser level (over budget) is the data it shows.
                  .reference = ReferenceModel::exact("voxel values"),
                  .benchRows = {{}}});  // the cost of the page table lookup when a volume is bricked
}

}  // namespace volren
