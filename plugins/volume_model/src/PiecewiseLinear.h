#pragma once
// Internal to volume_model: the piecewise-linear curves of TF preset files (ParaView, Slicer).
#include <iterator>
#include <map>

namespace volren {

/// Piecewise-linear function through (x, y) pairs, constant beyond the ends (VTK's clamping).
inline double piecewiseLinear(const std::map<double, double>& f, double x)
{
    auto upper = f.lower_bound(x);
    if (upper == f.begin()) return upper->second;
    if (upper == f.end()) return f.rbegin()->second;
    auto lower = std::prev(upper);
    const double t = (x - lower->first) / (upper->first - lower->first);
    return lower->second + t * (upper->second - lower->second);
}

}  // namespace volren
