// Classification implementations.
#include "CommonBindings.h"

#include "../resources/TextureCache.h"

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

/// The window values u0 <= u1 of texel values [lo, hi] under u = v * scale + offset, clamped
/// to [0, 1] as the GLSL clamps them; false when the map gives NaN (no bound).
bool windowedRange(double scale, double offset, double lo, double hi, double& u0, double& u1)
{
    u0 = lo * scale + offset;
    u1 = hi * scale + offset;
    if (std::isnan(u0) || std::isnan(u1)) return false;
    if (u0 > u1) std::swap(u0, u1);
    u0 = std::clamp(u0, 0.0, 1.0);
    u1 = std::clamp(u1, 0.0, 1.0);
    return true;
}

/// The table entries linear filtering may mix for texel values [lo, hi], with one more on each
/// side for float rounding; false when the range is NaN (no bound).
bool entriesOf(double scale, double offset, double lo, double hi, double last, int& a, int& b)
{
    double u0 = 0.0, u1 = 0.0;
    if (!windowedRange(scale, offset, lo, hi, u0, u1)) return false;
    a = std::max(0, int(std::floor(u0 * last)) - 1);
    b = std::min(int(last), int(std::ceil(u1 * last)) + 1);
    return true;
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
        int a = 0, b = 0;
        if (!entriesOf(scale, offset, lo, hi, last, a, b)) return true;
        return opaqueBefore[std::size_t(b) + 1] > opaqueBefore[std::size_t(a)];
    };
}

/// CPU mirror of the table lookup's variation: over the entries [a, b] a window range may mix,
/// the opacity varies by at most max a - min a and an opacity-weighted colour component (the
/// product of two interpolants for tf1d, the interpolated product for premultiplied) by at most
/// max a * max c - min a * min c. Range minima and maxima come from sparse tables (O(1) a cell).
std::function<double(double, double)> tableVariation(const BindContext& c)
{
    const auto [scale, offset] = bindings::windowMap(c);
    const std::vector<osg::Vec4> table = c.transfer.lookupTable();
    const std::size_t n = table.size();
    // levels[k][i]: min and max of each component over entries [i, i + 2^k).
    struct Span
    {
        osg::Vec4 lo, hi;
    };
    std::vector<std::vector<Span>> levels(1);
    for (const osg::Vec4& e : table) levels[0].push_back({e, e});
    for (std::size_t k = 1; (std::size_t(1) << k) <= n; ++k) {
        const std::vector<Span>& prev = levels[k - 1];
        std::vector<Span> next(n - (std::size_t(1) << k) + 1);
        for (std::size_t i = 0; i < next.size(); ++i) {
            const Span& x = prev[i];
            const Span& y = prev[i + (std::size_t(1) << (k - 1))];
            for (int j = 0; j < 4; ++j) {
                next[i].lo[j] = std::min(x.lo[j], y.lo[j]);
                next[i].hi[j] = std::max(x.hi[j], y.hi[j]);
            }
        }
        levels.push_back(std::move(next));
    }
    const double last = double(n) - 1.0;
    return [scale, offset, levels = std::move(levels), last](double lo, double hi) {
        int a = 0, b = 0;
        if (!entriesOf(scale, offset, lo, hi, last, a, b)) return 1.0;
        const std::size_t count = std::size_t(b - a + 1);
        std::size_t k = 0;
        while ((std::size_t(2) << k) <= count) ++k;
        const auto& x = levels[k][std::size_t(a)];
        const auto& y = levels[k][std::size_t(b) + 1 - (std::size_t(1) << k)];
        osg::Vec4 mn, mx;
        for (int j = 0; j < 4; ++j) {
            mn[j] = std::min(x.lo[j], y.lo[j]);
            mx[j] = std::max(x.hi[j], y.hi[j]);
        }
        double v = double(mx.a()) - mn.a();
        for (int j = 0; j < 3; ++j) v = std::max(v, double(mx.a()) * mx[j] - double(mn.a()) * mn[j]);
        return v;
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
                  .reference = ReferenceModel::none("a grey ramp over the window, not the transfer function"),
                  .mayShow = [](const BindContext& c) -> std::function<bool(double, double)> {
                      return [&c](double lo, double hi) {  // opacity = u: positive somewhere (float slack)
                          const double u = largestWindowed(c, lo, hi);
                          return std::isnan(u) || u > -1e-6;
                      };
                  },
                  .variation = [](const BindContext& c) -> std::function<double(double, double)> {
                      const auto [scale, offset] = bindings::windowMap(c);
                      return [scale, offset](double lo, double hi) {  // opacity u, colour u: u^2 weighted
                          double u0 = 0.0, u1 = 0.0;
                          if (!windowedRange(scale, offset, lo, hi, u0, u1)) return 1.0;
                          return std::max(u1 - u0, u1 * u1 - u0 * u0) + 1e-6;
                      };
                  }});

    // The transfer function as an RGBA 1D table over the window (TextureCache::table), plain or
    // with colour premultiplied by opacity; one per TF, remade when it changes.
    registry.addAuxKind({.name = "transfer function table", .provide = [](AuxRequest& r) -> osg::Texture* {
                             return r.textures.table(r.context.transfer, false, r.cull);
                         }});
    registry.addAuxKind({.name = "premultiplied table", .provide = [](AuxRequest& r) -> osg::Texture* {
                             return r.textures.table(r.context.transfer, true, r.cull);
                         }});

    registry.add({.slot = "Classification",
                  .name = "tf1d",
                  .uniforms = bindings::window,
                  .textures = {{"volren_transferFunction", "sampler1D"}},
                  .needs = {"transfer function table"},
                  .bind =
                      [](BindContext& c) {
                          bindings::bindWindow(c);
                          c.texture("volren_transferFunction", c.aux.at("transfer function table").get());
                      },
                  .traits = leaf,
                  .reference = ReferenceModel::exact("post-classified transfer function"),
                  .mayShow = tableMirror,
                  .variation = tableVariation});

    registry.add({.slot = "Classification",
                  .name = "premultiplied",
                  .uniforms = bindings::window,
                  .textures = {{"volren_premultipliedTable", "sampler1D"}},
                  .needs = {"premultiplied table"},
                  .bind =
                      [](BindContext& c) {
                          bindings::bindWindow(c);
                          c.texture("volren_premultipliedTable", c.aux.at("premultiplied table").get());
                      },
                  .traits = leaf,
                  // Colour premultiplied in the table, interpolated between its entries as such.
                  .reference = ReferenceModel::approximate("post-classified transfer function", 0.01),
                  .benchRows = {{}},
                  .mayShow = tableMirror,  // the same opacities as tf1d
                  .variation = tableVariation});

    registry.add({.slot = "Classification",
                  .name = "threshold",
                  .uniforms = bindings::window + std::vector<UniformDecl>{{"volren_threshold", "float", ""}},
                  .textures = {{"volren_transferFunction", "sampler1D"}},
                  .needs = {"transfer function table"},
                  .parameters = {{.key = "threshold", .defaultValue = 0.5, .lo = 0.0, .hi = 1.0,
                                  .help = "level of the threshold classification, as a fraction of the value window"}},
                  .bind =
                      [](BindContext& c) {
                          bindings::bindWindow(c);
                          c.uniform("volren_threshold", float(c.settings.number("threshold")));
                          c.texture("volren_transferFunction", c.aux.at("transfer function table").get());
                      },
                  .traits = leaf,
                  .reference = ReferenceModel::none("opaque above a threshold, not the transfer function's opacity"),
                  .mayShow = [](const BindContext& c) -> std::function<bool(double, double)> {
                      const double threshold = c.settings.number("threshold");
                      return [&c, threshold](double lo, double hi) {  // opaque where u reaches the threshold
                          const double u = std::clamp(largestWindowed(c, lo, hi), 0.0, 1.0);
                          return std::isnan(u) || u >= threshold - 1e-6;
                      };
                  }});
}

}  // namespace volren
