// Acceleration implementations: where along the ray sampling is worth it (empty-space skipping).
#include "CommonBindings.h"

#include <volume_renderer/MacrocellGrid.h>
#include <volume_renderer/ShaderFunctionRegistry.h>

#include <volume_model/RenderSettings.h>
#include <volume_model/Volume.h>

namespace volren {

namespace {

const std::vector<UniformDecl> cellUniforms = {
    {"volren_cellScale", "vec3", ""}, {"volren_cellCount", "vec3", ""}, {"volren_coarseFactor", "float", ""}};

/// The macrocell geometry: texture coordinate -> cell, cells per axis, cells per coarse cell.
void bindCells(BindContext& c)
{
    const osg::Vec3i d = c.volume.dims();
    const int size = c.settings.macrocellSize;
    const osg::Vec3i cells((d.x() + size - 1) / size, (d.y() + size - 1) / size, (d.z() + size - 1) / size);
    c.uniform("volren_cellScale", osg::Vec3f(float(d.x()) / float(size), float(d.y()) / float(size), float(d.z()) / float(size)));
    c.uniform("volren_cellCount", osg::Vec3f(float(cells.x()), float(cells.y()), float(cells.z())));
    c.uniform("volren_coarseFactor", float(occupancyCoarseFactor));
}

}  // namespace

void registerAccelerationFunctions(ShaderFunctionRegistry& registry)
{
    registry.add({.slot = "Acceleration", .name = "null", .traits = {.calls = SlotList{}}});

    // The pass builds the grids from the volume's macrocell value ranges with the
    // Reconstruction's footprint as apron (and, for opacity, the Classification's CPU mirror).
    registry.add({.slot = "Acceleration",
                  .name = "occupancy",
                  .uniforms = cellUniforms,
                  .textures = {{"volren_occupancy", "sampler3D"}},
                  .needs = {AuxData::OccupancyGrid},
                  .bind =
                      [](BindContext& c) {
                          bindCells(c);
                          c.texture("volren_occupancy", c.aux.at(AuxData::OccupancyGrid).get());
                      },
                  .traits = {.calls = SlotList{}, .skips = "opacity"}});
    registry.add({.slot = "Acceleration",
                  .name = "range",
                  .uniforms = cellUniforms,
                  .textures = {{"volren_cellRanges", "sampler3D"}},
                  .needs = {AuxData::MacrocellRanges},
                  .bind =
                      [](BindContext& c) {
                          bindCells(c);
                          c.texture("volren_cellRanges", c.aux.at(AuxData::MacrocellRanges).get());
                      },
                  .traits = {.calls = SlotList{}, .skips = "extremum"}});
}

}  // namespace volren
