// Acceleration implementations: where along the ray sampling is worth it (empty-space skipping).
#include "CommonBindings.h"

#include "../resources/TextureCache.h"

#include <volume_renderer/MacrocellGrid.h>
#include <volume_renderer/ShaderFunctionRegistry.h>

#include <volume_model/RenderSettings.h>
#include <volume_model/Volume.h>

#include <stdexcept>

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

/// The bound Reconstruction's footprint: the apron of the macrocell value ranges.
int footprintOf(const AuxRequest& r)
{
    const ShaderFunction* reconstruction = r.chosen("Reconstruction");
    if (!reconstruction || reconstruction->traits.footprint < 0)  // the policy's rules exclude this
        throw std::logic_error("macrocell grid without a Reconstruction footprint");
    return reconstruction->traits.footprint;
}

/// The occupancy grid of the bound volume under the bound Classification's opacity mirror; with
/// `homogeneity`, visible cells tell whether the classification varies within adaptiveTolerance
/// there (none is homogeneous for a Classification without a variation mirror or a volume with
/// NaN voxels, whose interpolated samples turn transparent).
osg::Texture* occupancyFor(AuxRequest& r, bool homogeneity)
{
    const BindContext& context = r.context;
    const ShaderFunction* classification = r.chosen("Classification");
    const int footprint = footprintOf(r);
    if (!classification || !classification->mayShow)  // the policy's rules exclude this
        throw std::logic_error("occupancy grid without a Classification mirror");
    // What the classification's opacity depends on besides the volume and the TF.
    std::string key = classification->name;
    bindings::appendParameterValues(key, context.settings, *classification);
    const bool varies = homogeneity && classification->variation && context.volume.nonFiniteCount() == 0;
    const double tolerance = varies ? context.settings.number("adaptiveTolerance") : -1.0;
    if (homogeneity) {
        key += "|homogeneous within ";
        bindings::appendBytes(key, tolerance);
    }
    const GridShape shape = gridShapeFor(context.volume.dims(), context.settings.macrocellSize, footprint, context.lod);
    return r.textures.occupancy(
        context.volume, context.transfer, shape.cellSize, shape.apron, key,
        [&]() -> std::pair<TextureCache::CellTest, TextureCache::CellTest> {
            TextureCache::CellTest homogeneous;
            if (varies)
                homogeneous = [variation = classification->variation(context), tolerance](double lo, double hi) {
                    return variation(lo, hi) <= tolerance;
                };
            else if (homogeneity)
                homogeneous = [](double, double) { return false; };
            return {classification->mayShow(context), homogeneous};
        },
        r.cull, r.anyVisible);
}

/// A skipping over a macrocell grid texture `sampler` made from `aux`, leaping by `skips`, with
/// `includes` after the cell geometry (the leap, the steps per sample).
ShaderFunction gridSkipping(const std::string& name, const std::string& sampler, const std::string& aux, const std::string& skips,
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
            .traits = {.calls = SlotList{}, .skips = skips},
            .reference = ReferenceModel::exact("every sample")};  // it leaps only over what adds nothing
}

}  // namespace

void registerAccelerationFunctions(ShaderFunctionRegistry& registry)
{
    registry.add({.slot = "Acceleration",
                  .name = "null",
                  .includes = {"Acceleration/every_step.glsl"},
                  .traits = {.calls = SlotList{}},
                  .reference = ReferenceModel::exact("every sample"),
                  .benchRows = {{}}});  // skipping off: the same image, the cost of marching all

    // The grids are made from the volume's macrocell value ranges with the Reconstruction's
    // footprint as apron (and, for opacity, the Classification's CPU mirror), per macrocell of
    // the volume (MacrocellGrid.h) as 3D textures read with texelFetch:
    // - occupancy grid: whether any sample in the cell may be visible under the current TF (R8);
    // - homogeneity grid: the occupancy grid with visible cells told apart: 255 where the
    //   classification varies by at most the node's adaptiveTolerance over the cell's values
    //   (the Classification's variation mirror), else 128 (adaptive sampling);
    // - macrocell ranges: the smallest and largest texel value its samples can read (RG16F,
    //   bounds rounded outwards).
    // An occupancy grid with no visible cell hides the volume (nothing to draw).
    registry.addAuxKind({.name = "occupancy grid", .provide = [](AuxRequest& r) { return occupancyFor(r, false); }});
    registry.addAuxKind({.name = "homogeneity grid", .provide = [](AuxRequest& r) { return occupancyFor(r, true); }});
    registry.addAuxKind({.name = "macrocell ranges", .provide = [](AuxRequest& r) {
                             const BindContext& c = r.context;
                             const GridShape shape = gridShapeFor(c.volume.dims(), c.settings.macrocellSize, footprintOf(r), c.lod);
                             return r.textures.ranges(c.volume, shape.cellSize, shape.apron, r.cull);
                         }});
    registry.add(gridSkipping("occupancy", "volren_occupancy", "occupancy grid", "opacity",
                              {"Acceleration/occupancy_leap.glsl", "Acceleration/every_step.glsl"}));
    registry.add(gridSkipping("range", "volren_cellRanges", "macrocell ranges", "extremum",
                              {"Acceleration/every_step.glsl"}));

    // Skipping as occupancy, and in cells where the classification stays within the node's
    // adaptiveTolerance (the Classification's variation mirror) one sample for up to
    // adaptiveSteps steps.
    ShaderFunction adaptive = gridSkipping("adaptive", "volren_occupancy", "homogeneity grid", "opacity",
                                           {"Acceleration/occupancy_leap.glsl"});
    adaptive.uniforms.push_back({"volren_adaptiveSteps", "int", ""});
    adaptive.traits.approximates = true;
    adaptive.reference = ReferenceModel::approximate("every sample", 0.02);  // at the default tolerance
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
