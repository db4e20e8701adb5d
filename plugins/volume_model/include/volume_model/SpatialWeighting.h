#pragma once
#include <array>
#include <string>
#include <utility>
#include <vector>

namespace volren {

/// A weighting function over one normalised volume coordinate u in [0,1] (texture space: voxel
/// i's centre at (i + 0.5)/n): piecewise linear through its knots, constant beyond the first and
/// the last; no knots: 1 everywhere.
struct WeightCurve
{
    static constexpr std::size_t maxKnots = 16;  ///< the most knots a curve may have
    /// (u, weight) with u strictly increasing in [0, 1] and weights in [0, 1].
    std::vector<std::pair<double, double>> knots;

    /// The weight at u.
    double operator()(double u) const;
    /// Whether it is 1 everywhere.
    bool identity() const;
    /// Knots as "u:w,u:w,..." (empty for none); parse() reads it back exactly.
    std::string text() const;
    /// Reads "u:w,u:w,...", "ramp:A" (0 at both ends, 1 from A to 1 - A; 0 < A <= 0.5), or
    /// "" / "none" (no knots). False with the reason in `error` for anything else.
    static bool parse(const std::string& text, WeightCurve& out, std::string& error);

    bool operator==(const WeightCurve& o) const { return knots == o.knots; }
    bool operator!=(const WeightCurve& o) const { return !(*this == o); }
};

/// Spatial weighting of a volume (Weighting slot, implementation axes): one curve per axis of its
/// normalised coordinates; a sample's opacity is scaled by the product of the three weights at
/// its position (microscopy: fading out the noisy first and last slices of a stack).
struct SpatialWeighting
{
    std::array<WeightCurve, 3> axes;  ///< x, y, z

    /// The product of the axes' weights at normalised position (x, y, z).
    double operator()(double x, double y, double z) const { return axes[0](x) * axes[1](y) * axes[2](z); }
    /// Whether every weight is 1.
    bool identity() const { return axes[0].identity() && axes[1].identity() && axes[2].identity(); }

    bool operator==(const SpatialWeighting& o) const { return axes == o.axes; }
    bool operator!=(const SpatialWeighting& o) const { return !(*this == o); }
};

struct RenderSettings;

/// The spatial weighting the parameters weightX, weightY and weightZ (declared by the Weighting
/// slot's axes implementation) of `settings` describe.
SpatialWeighting spatialWeighting(const RenderSettings& settings);

}  // namespace volren
