// RayTraversal implementations.
#include "CommonBindings.h"

#include <volume_renderer/ShaderFunctionRegistry.h>

#include <volume_model/RenderSettings.h>
#include <volume_model/TransferFunction.h>
#include <volume_model/Volume.h>

#include <cmath>

namespace volren {

namespace {

using bindings::operator+;

const std::vector<UniformDecl> marching = {{"volren_sampleDistance", "float", ""},
                                           {"volren_referenceStep", "float", ""},
                                           {"volren_terminationDepth", "float", ""},
                                           {"volren_terminationOpacity", "float", ""}};

void bindMarching(BindContext& c)
{
    bindings::bindGeometry(c);
    c.uniform("volren_sampleDistance", float(c.sampleDistance));
    c.uniform("volren_referenceStep", float(c.volume.minSpacing()));
    // Opacity A reached <=> optical depth -log(1-A) reached; A = 1 never terminates early.
    const double threshold = c.settings.earlyTerminationThreshold;
    c.uniform("volren_terminationDepth", float(threshold >= 1.0 ? 1e30 : -std::log1p(-threshold)));
    c.uniform("volren_terminationOpacity", float(threshold));
}

/// Data value of the isosurface: the setting, else the first TF value with any opacity.
double isoValueOf(const BindContext& c)
{
    if (!std::isnan(c.settings.isoValue)) return c.settings.isoValue;
    const std::vector<osg::Vec4> table = c.transfer.lookupTable();
    const double lo = c.transfer.domainMin(), hi = c.transfer.domainMax();
    for (std::size_t i = 0; i < table.size(); ++i)
        if (table[i].a() > 0.0f) return lo + (hi - lo) * double(i) / double(table.size() - 1);
    return hi;
}

ShaderFunction traversal(const std::string& name, std::vector<UniformDecl> extra = {})
{
    ShaderFunction f;
    f.calls = {"Reconstruction", "Classification", "ClipPosition", "Shading", "Acceleration"};
    f.slot = "RayTraversal";
    f.name = name;
    f.file = "RayTraversal/" + name + ".glsl";
    f.includes = {"RayTraversal/march.glsl"};
    f.uniforms = bindings::geometry + marching + extra;
    f.bind = [](BindContext& c) { bindMarching(c); };
    return f;
}

}  // namespace

void registerRayTraversalFunctions(ShaderFunctionRegistry& registry)
{
    ShaderFunction none{"RayTraversal", "null", "RayTraversal/null.glsl", "", {}, {}, {}, {}, nullptr, false, {}};
    none.calls = {"RayTraversal"};  // calls nothing else (a slot list may not be empty)
    registry.add(none);
    registry.add(traversal("dvr_front_to_back"));
    registry.add(traversal("dvr_back_to_front"));
    for (const char* name : {"mip", "minip", "average"}) {  // projections: they never shade
        ShaderFunction f = traversal(name);
        f.calls = {"Reconstruction", "Classification", "ClipPosition"};
        registry.add(f);
    }

    ShaderFunction mida = traversal("mida", bindings::window);
    mida.bind = [](BindContext& c) {
        bindMarching(c);
        bindings::bindWindow(c);
    };
    registry.add(mida);

    ShaderFunction gmip = traversal("gmip", bindings::window + std::vector<UniformDecl>{bindings::gradientScale});
    gmip.calls = {"Gradient", "Classification", "ClipPosition"};
    gmip.bind = [](BindContext& c) {
        bindMarching(c);
        bindings::bindWindow(c);
        bindings::bindGradientScale(c);
    };
    registry.add(gmip);

    ShaderFunction iso = traversal("isosurface", {{"volren_isoTexel", "float", ""}});
    iso.writesDepth = true;
    iso.bind = [](BindContext& c) {
        bindMarching(c);
        const double stored = (isoValueOf(c) - c.volume.rescaleIntercept()) / c.volume.rescaleSlope();
        c.uniform("volren_isoTexel", float(stored / normalisedScale(c.volume.type())));
    };
    registry.add(iso);
}

}  // namespace volren
