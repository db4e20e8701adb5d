#pragma once
#include <cstdint>
#include <vector>

namespace volren {

/// Voxel-value histogram over [minValue, maxValue] in data units (after rescale).
struct Histogram
{
    double minValue = 0.0;              ///< lower edge of the first bin
    double maxValue = 0.0;              ///< upper edge of the last bin
    std::vector<std::uint64_t> counts;  ///< voxels per bin
    std::uint64_t ignored = 0;          ///< NaN voxels, not counted in any bin

    /// Total number of counted voxels.
    std::uint64_t total() const;
    /// Width of one bin in data units.
    double binWidth() const;
    /// Centre value of bin `i`.
    double binCentre(std::size_t i) const;
    /// Data value below which fraction `p` (0..1) of the counted voxels lie.
    double percentile(double p) const;
    /// Otsu's threshold between background and foreground, in data units.
    double otsuThreshold() const;
};

}  // namespace volren
