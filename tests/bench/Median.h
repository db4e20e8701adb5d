#pragma once
// The benchmark programs' summary of repeated timings.
#include <algorithm>
#include <vector>

namespace volren::bench {

/// The median of `v` (the upper one of an even count; 0 when empty).
inline double median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
}

}  // namespace volren::bench
