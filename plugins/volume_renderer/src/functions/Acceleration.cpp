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

/// The macrocell geometry: texture coordinate -> cell, cells per axis, cells per coarse cell
/// (cells grow with the mip level sampled: MacrocellGrid.h's gridShapeFor).
void bindCells(BindContext& c)
{
    const osg::Vec3i d = c.volume.dims();
    const int size = gridShapeFor(d, c.settings.macrocellSize, 0, c.lod).cellSize;
    const osg::Vec3i cells((d.x() + size - 1) / size, (d.y() + size - 1) / size, (d.z() + size - 1) / size);
    c.uniform("volren_cellScale", osg::Vec3f(float(d.x()) / float(size), float(d.y()) / float(size), float(d.z()) / float(size)));
    c.uniform("volren_cellCount", osg::Vec3f(float(cells.x()), float(cells.y()), float(cells.z())));
    c.uniform("volren_coarseFactor", float(occupancyCoarseFactor));
}

/// A skipping over a macrocell grid texture `sampler` made from `aux`, leaping by `skips`, with
/// `includes` after the cell geometry (the leap, the steps per sample).
ShaderFunction gridSkipping(const std::string& name, const std::string& sampler, AuxData aux, const std::string& skips,
                            const std::vector<std::string>& includes)
{
    std::vector<std::string> files = {"Acceleration/cells.glsl"};
    files.insert(files.end(), includes.begin(), includes.end());
    return {.slot = "Acceleration",
            .name = name,
            .includes = files,
            .uniforms = cellUniforms,
            .textures = {{sampler, "sampler3D"}},
            .needs = {aux},
            .bind =
                [sampler, aux](BindContext& c) {
                    bindCells(c);
                    c.texture(sampler, c.aux.at(aux).get());
                },
            .traits = {.calls = SlotList{}, .skips = skips}};
}

}  // namespace

void registerAccelerationFunctions(ShaderFunctionRegistry& registry)
{
    registry.add({.slot = "Acceleration",
                  .name = "null",
                  .includes = {"Acceleration/every_step.glsl"},
                  .traits = {.calls = SlotList{}},
                  .benchRows = {{}}});  // skipping off: the same image, the cost of marching all

    // The pass builds the grids from the volume's macrocell value ranges with the
    // Reconstruction's footprint as apron (and, for opacity, the Classification's CPU mirror).
    registry.add(gridSkipping("occupancy", "volren_occupancy", AuxData::OccupancyGrid, "opacity",
                              {"Acceleration/occupancy_leap.glsl", "Acceleration/every_step.glsl"}));
    registry.add(gridSkipping("range", "volren_cellRanges", AuxData::MacrocellRanges, "extremum",
                              {"Acceleration/every_step.glsl"}));

    // Skipping as occupancy, and in cells where the classification stays within the node's
    // adaptiveTolerance (the Classification's variation mirror) one sample for up to
    // adaptiveSteps steps.
    ShaderFunction adaptive = gridSkipping("adaptive", "volren_occupancy", AuxData::HomogeneityGrid, "opacity",
                                           {"Acceleration/occupancy_leap.glsl"});
    adaptive.uniforms.push_back({"volren_adaptiveSteps", "int", ""});
    adaptive.traits.approximates = true;
    adaptive.benchRows = {{}, {{"adaptiveSteps", "8"}}, {{"adaptiveTolerance", "0.02"}}};
    adaptive.parameters = {{.key = "adaptiveTolerance", .defaultValue = 1.0 / 256.0, .lo = 0.0, .hi = 1.0,
                            .help = "largest change of the classified RGBA over a macrocell that counts as homogeneous",
                            .label = "adaptive tolerance", .panel = {PanelHint::LogSlider, 1e-4, 0.1}},
                           {.key = "adaptiveSteps", .type = ParameterType::Integer, .defaultValue = 4, .lo = 1, .hi = 64,
                            .unit = "steps", .help = "most march steps one sample stands for in a homogeneous macrocell",
                            .label = "adaptive steps", .panel = {PanelHint::Slider, 1, 64}}};
    adaptive.bind = [grid = adaptive.bind](BindContext& c) {
        grid(c);
        c.uniform("volren_adaptiveSteps", c.settings.parameter<int>("adaptiveSteps"));
    };
    registry.add(adaptive);
}

}  // namespace volren
