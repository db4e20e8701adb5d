// RayTraversal implementations, and the multi-volume set's traversal.
#include "CommonBindings.h"

#include <volume_renderer/ShaderFunctionRegistry.h>

#include <volume_model/RenderSettings.h>
#include <volume_model/TransferFunction.h>
#include <volume_model/Volume.h>

#include <cmath>
#include <limits>

namespace volren {

namespace {

using bindings::operator+;

const std::vector<UniformDecl> marching = {{"volren_sampleDistance", "float", ""},
                                           {"volren_referenceStep", "float", ""},
                                           {"volren_terminationDepth", "float", ""},
                                           {"volren_terminationOpacity", "float", ""}};

/// Optical depth at which marching stops: opacity A reached <=> -log(1-A); A = 1 never stops.
float terminationDepth(double threshold)
{
    return float(threshold >= 1.0 ? 1e30 : -std::log1p(-threshold));
}

void bindMarching(BindContext& c)
{
    bindings::bindGeometry(c);
    c.uniform("volren_sampleDistance", float(c.sampleDistance));
    c.uniform("volren_referenceStep", float(c.volume.minSpacing()));
    c.uniform("volren_terminationDepth", terminationDepth(c.settings.earlyTerminationThreshold));
    c.uniform("volren_terminationOpacity", float(c.settings.earlyTerminationThreshold));
}

/// Data value of the isosurface: the setting, else the first TF value with any opacity.
double isoValueOf(const BindContext& c)
{
    if (const double iso = c.settings.number("isoValue"); !std::isnan(iso)) return iso;
    const std::vector<osg::Vec4> table = c.transfer.lookupTable();
    const double lo = c.transfer.domainMin(), hi = c.transfer.domainMax();
    for (std::size_t i = 0; i < table.size(); ++i)
        if (table[i].a() > 0.0f) return lo + (hi - lo) * double(i) / double(table.size() - 1);
    return hi;
}

/// A marching traversal in RayTraversal/<name>.glsl that calls `calls`.
ShaderFunction traversal(const std::string& name, SlotList calls, std::vector<UniformDecl> extra = {})
{
    return {.slot = "RayTraversal",
            .name = name,
            .includes = {"RayTraversal/march.glsl"},
            .uniforms = bindings::geometry + marching + extra,
            .bind = bindMarching,
            .traits = {.calls = std::move(calls)},
            .reference = ReferenceModel::none("the reference integrates emission-absorption only; closed forms check it")};
}

const SlotList compositing = {"Reconstruction", "Classification", "ClipPosition", "Shading"};
const SlotList projecting = {"Reconstruction", "Classification", "ClipPosition"};

}  // namespace

void registerRayTraversalFunctions(ShaderFunctionRegistry& registry)
{
    registry.add({.slot = "RayTraversal",
                  .name = "null",
                  .traits = {.calls = SlotList{}},
                  .reference = ReferenceModel::none("it marches nothing: the sweep's 'drawn' check is its test")});

    // The compositing traversals leap over what the Acceleration proves transparent; their
    // samples' opacities are scaled by the Weighting.
    const SlotList skipping = {"Reconstruction", "Classification", "ClipPosition", "Shading", "Acceleration"};
    const SlotList weighted = {"Reconstruction", "Classification", "ClipPosition", "Shading", "Acceleration", "Weighting"};
    ShaderFunction frontToBack = traversal("dvr_front_to_back", weighted);
    frontToBack.traits.sharesRayAs = "emission_absorption";
    frontToBack.traits.aliases = {"dvr"};
    frontToBack.traits.skips = "opacity";
    frontToBack.reference = ReferenceModel::exact("emission-absorption");
    registry.add(frontToBack);
    ShaderFunction backToFront = traversal("dvr_back_to_front", weighted);
    backToFront.traits.sharesRayAs = "emission_absorption";
    backToFront.traits.skips = "opacity";
    backToFront.reference = ReferenceModel::exact("emission-absorption");
    registry.add(backToFront);

    // The projections never shade; MIP and MinIP leap over what cannot pass their running extremum
    // and scale the opacity of the extremum by the Weighting there (samples of weight 0 do not count).
    for (const char* name : {"mip", "minip"}) {
        ShaderFunction extremum =
            traversal(name, {"Reconstruction", "Classification", "ClipPosition", "Acceleration", "Weighting"});
        extremum.includes.push_back("RayTraversal/extremum.glsl");
        extremum.traits.skips = "extremum";
        extremum.traits.skipsByDefault = std::string(name) == "minip";  // docs/bench/skipping.md
        if (std::string(name) == "mip") extremum.traits.sharesRayAs = "maximum";
        registry.add(extremum);
    }
    registry.add(traversal("average", projecting));

    ShaderFunction mida = traversal("mida", compositing, bindings::window);
    mida.bind = [](BindContext& c) {
        bindMarching(c);
        bindings::bindWindow(c);
    };
    registry.add(mida);

    ShaderFunction gmip = traversal("gmip", {"Gradient", "Classification", "ClipPosition"},
                                    bindings::window + std::vector<UniformDecl>{bindings::gradientScale});
    gmip.traits.required = {"Gradient"};
    gmip.bind = [](BindContext& c) {
        bindMarching(c);
        bindings::bindWindow(c);
        bindings::bindGradientScale(c);
    };
    registry.add(gmip);

    ShaderFunction iso = traversal("isosurface", skipping, {{"volren_isoTexel", "float", ""}});
    iso.traits.writesDepth = true;
    iso.parameters = {{.key = "isoValue", .defaultValue = std::numeric_limits<double>::quiet_NaN(),
                       .lo = std::numeric_limits<double>::lowest(), .hi = std::numeric_limits<double>::max(),
                       .emptyMeans = "the TF's first opaque value", .help = "data value of the isosurface",
                       .label = "iso value", .panel = {PanelHint::Text}}};
    iso.traits.skips = "extremum";  // leaps over cells whose values stay below the iso value
    iso.bind = [](BindContext& c) {
        bindMarching(c);
        const double stored = (isoValueOf(c) - c.volume.rescaleIntercept()) / c.volume.rescaleSlope();
        c.uniform("volren_isoTexel", float(stored / normalisedScale(c.volume.type())));
    };
    registry.add(iso);

    // A multi-volume set's traversals: bound once for the set, with the set's box, the finest
    // member step (BindContext::sampleDistance) and the strictest member's early termination;
    // the members' samples come from their MultiVolume/member glue.
    auto setTraversal = [](const std::string& name, const std::string& members, const std::string& combines,
                           const std::string& memberTraversal) {
        return ShaderFunction{
            .slot = "RayTraversal",
            .name = name,
            .file = "MultiVolume/" + name + ".glsl",
            .includes = combines == "media" ? std::vector<std::string>{"RayTraversal/march.glsl"}
                                            : std::vector<std::string>{"RayTraversal/march.glsl", "MultiVolume/add_images.glsl"},
            .uniforms = bindings::geometry + std::vector<UniformDecl>{{"volren_sampleDistance", "float", ""},
                                                                     {"volren_terminationDepth", "float", ""}},
            .bind =
                [](BindContext& c) {
                    bindings::bindGeometry(c);
                    c.uniform("volren_sampleDistance", float(c.sampleDistance));
                    c.uniform("volren_terminationDepth", terminationDepth(c.settings.earlyTerminationThreshold));
                },
            .traits = {.calls = SlotList{},
                       .sharesRayAs = members,
                       .memberTraversal = memberTraversal,
                       .combines = combines,
                       .multiVolume = true,
                       .skips = combines == "maxima" ? "" : "opacity"}};
    };
    // Media add where members overlap (the default); `composite` names it.
    ShaderFunction sum = setTraversal("sum_of_media", "emission_absorption", "media", "dvr_front_to_back");
    sum.traits.aliases = {"composite"};
    registry.add(sum);
    // Each member's own emission-absorption image, added (napari's additive blending).
    registry.add(setTraversal("additive", "emission_absorption", "images", "dvr_front_to_back"));
    // Each member's maximum intensity projection, added (napari's MIP look).
    registry.add(setTraversal("mip_additive", "maximum", "maxima", "mip"));
}

}  // namespace volren
