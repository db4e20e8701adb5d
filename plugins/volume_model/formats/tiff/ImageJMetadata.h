#pragma once
#include "StackLayout.h"

#include <optional>
#include <string>

namespace volren::tiff {

/// The parts of an ImageJ ImageDescription ("ImageJ=1.53q\nimages=40\nslices=40\n...") that
/// shape a stack.
struct ImageJMetadata
{
    std::optional<std::size_t> images, channels, slices, frames;  ///< counts, when given
    std::optional<double> spacing;                                  ///< z step, when given
    std::string unit;                                               ///< length unit ("µm", "micron", ...)
};

/// Whether `description` is ImageJ's (starts with "ImageJ=").
bool isImageJDescription(const std::string& description);

/// Parses `description`; throws std::runtime_error("name: reason") for counts that are not
/// positive integers or a spacing that is not a positive number.
ImageJMetadata parseImageJDescription(const std::string& description, const std::string& name);

/// The page layout (order XYCZT) for `pages` pages; throws std::runtime_error("name: reason")
/// when the counts disagree with each other or with the page count.
StackLayout imageJLayout(const ImageJMetadata& meta, std::size_t pages, const std::string& name);

}  // namespace volren::tiff
