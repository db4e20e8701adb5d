// Classification implementations.
#include "CommonBindings.h"

#include <volume_renderer/ShaderFunctionRegistry.h>

#include <volume_model/RenderSettings.h>
#include <volume_model/TransferFunction.h>

#include <algorithm>
#include <cmath>

namespace volren {

using bindings::operator+;

namespace {

/// Largest unclamped window value u = v * scale + offset over texel values [lo, hi] (NaN when
/// the map is degenerate, e.g. 0 * inf).
double largestWindowed(const BindContext& c, double lo, double hi)
{
    const auto [scale, offset] = bindings::windowMap(c);
    return std::max(lo * scale + offset, hi * scale + offset);
}

/// CPU mirror of the GLSL's table lookup: some entry that linear filtering may mix for a
/// window value in the range has opacity.
std::function<bool(double, double)> tableMirror(const BindContext& c)
{
    const auto [scale, offset] = bindings::windowMap(c);
    const std::vector<osg::Vec4> table = c.transfer.lookupTable();
    std::vector<unsigned int> opaqueBefore(table.size() + 1, 0);  // entries with opacity before index
    for (std::size_t i = 0; i < table.size(); ++i) opaqueBefore[i + 1] = opaqueBefore[i] + (table[i].a() > 0.0f ? 1 : 0);
    const double last = double(table.size()) - 1.0;
    return [scale, offset, opaqueBefore = std::move(opaqueBefore), last](double lo, double hi) {
        double u0 = lo * scale + offset, u1 = hi * scale + offset;
        if (std::isnan(u0) || std::isnan(u1)) return true;
        if (u0 > u1) std::swap(u0, u1);
        u0 = std::clamp(u0, 0.0, 1.0);
        u1 = std::clamp(u1, 0.0, 1.0);
        // The two entries around u * last, and one more on each side for float rounding.
        const int a = std::max(0, int(std::floor(u0 * last)) - 1);
        const int b = std::min(int(last), int(std::ceil(u1 * last)) + 1);
        return opaqueBefore[std::size_t(b) + 1] > opaqueBefore[std::size_t(a)];
    };
}

}  // namespace

void registerClassificationFunctions(ShaderFunctionRegistry& registry)
{
    const ImplementationTraits leaf{.calls = SlotList{}};
    registry.add({.slot = "Classification",
                  .name = "null",
                  .uniforms = bindings::window,
                  .bind = bindings::bindWindow,
                  .traits = leaf,
                  .mayShow = [](const BindContext& c) -> std::function<bool(double, double)> {
                      return [&c](double lo, double hi) {  // opacity = u: positive somewhere (float slack)
                          const double u = largestWindowed(c, lo, hi);
                          return std::isnan(u) || u > -1e-6;
                      };
                  }});

    registry.add({.slot = "Classification",
                  .name = "tf1d",
                  .uniforms = bindings::window,
                  .textures = {{"volren_transferFunction", "sampler1D"}},
                  .needs = {AuxData::TransferFunctionTable},
                  .bind =
                      [](BindContext& c) {
                          bindings::bindWindow(c);
                          c.texture("volren_transferFunction", c.aux.at(AuxData::TransferFunctionTable).get());
                      },
                  .traits = leaf,
                  .mayShow = tableMirror});

    registry.add({.slot = "Classification",
                  .name = "premultiplied",
                  .uniforms = bindings::window,
                  .textures = {{"volren_premultipliedTable", "sampler1D"}},
                  .needs = {AuxData::PremultipliedTable},
                  .bind =
                      [](BindContext& c) {
                          bindings::bindWindow(c);
                          c.texture("volren_premultipliedTable", c.aux.at(AuxData::PremultipliedTable).get());
                      },
                  .traits = leaf,
                  .mayShow = tableMirror});  // the same opacities as tf1d

    registry.add({.slot = "Classification",
                  .name = "threshold",
                  .uniforms = bindings::window + std::vector<UniformDecl>{{"volren_threshold", "float", ""}},
                  .textures = {{"volren_transferFunction", "sampler1D"}},
                  .needs = {AuxData::TransferFunctionTable},
                  .bind =
                      [](BindContext& c) {
                          bindings::bindWindow(c);
                          c.uniform("volren_threshold", float(c.settings.threshold));
                          c.texture("volren_transferFunction", c.aux.at(AuxData::TransferFunctionTable).get());
                      },
                  .traits = leaf,
                  .mayShow = [](const BindContext& c) -> std::function<bool(double, double)> {
                      return [&c](double lo, double hi) {  // opaque where u reaches the threshold
                          const double u = std::clamp(largestWindowed(c, lo, hi), 0.0, 1.0);
                          return std::isnan(u) || u >= c.settings.threshold - 1e-6;
                      };
                  }});
}

}  // namespace volren
