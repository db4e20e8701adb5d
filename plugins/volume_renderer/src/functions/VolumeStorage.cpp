// VolumeStorage implementations: where the voxels a Reconstruction reads live.
#include "CommonBindings.h"

#include <volume_renderer/BrickPool.h>
#include <volume_renderer/ShaderFunctionRegistry.h>

#include <algorithm>

namespace volren {

void registerVolumeStorageFunctions(ShaderFunctionRegistry& registry)
{
    registry.add({.slot = "VolumeStorage", .name = "null", .traits = {.calls = SlotList{}}});
    // One 3D texture of the sampled mip level (16-bit texels of 8-bit data where texturePrecision
    // says so).
    registry.add({.slot = "VolumeStorage",
                  .name = "texture",
                  .textures = {bindings::volumeTexture},
                  .needs = {AuxData::VolumeTexture},
                  .bind = bindings::bindVolumeTexture,
                  .traits = {.calls = SlotList{}}});
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
                  .needs = {AuxData::BrickPool},
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
                  .benchRows = {{}}});  // the cost of the page table lookup when a volume is bricked
}

}  // namespace volren
