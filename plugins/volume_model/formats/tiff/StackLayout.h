#pragma once
#include <cstddef>
#include <string>

namespace volren::tiff {

/// Which page of a stack holds which channel, slice and time point.
struct StackLayout
{
    std::size_t channels = 1, slices = 1, frames = 1;  ///< image planes along C, Z, T
    std::string order = "CZT";                          ///< C, Z, T from fastest to slowest varying (ImageJ: XYCZT)

    /// channels * slices * frames, or 0 when that overflows.
    std::size_t pageCount() const;
    /// Channel, slice and time point of page `page`.
    void coordinates(std::size_t page, std::size_t& c, std::size_t& z, std::size_t& t) const;
};

/// Parses an OME DimensionOrder ("XYZCT", ...) into StackLayout::order; false when invalid.
bool parseDimensionOrder(const std::string& text, std::string& order);

}  // namespace volren::tiff
