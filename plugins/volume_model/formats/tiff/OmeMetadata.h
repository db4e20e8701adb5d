#pragma once
#include "StackLayout.h"

#include <volume_model/Volume.h>

#include <optional>
#include <string>
#include <vector>

namespace volren::tiff {

/// The first image's <Pixels> element of an OME-XML ImageDescription.
struct OmeMetadata
{
    std::size_t sizeX = 0, sizeY = 0, sizeZ = 1, sizeC = 1, sizeT = 1;  ///< OME sizes
    std::string order = "ZCT";                                          ///< DimensionOrder without "XY"
    std::optional<double> physicalX, physicalY, physicalZ;               ///< voxel size, when given
    std::string physicalUnit;  ///< PhysicalSizeXUnit (OME's default µm where PhysicalSizeX is given)
    std::size_t images = 1;                                              ///< <Image> elements in the file
    /// The first image's <Channel> elements in order: Name and Color (a signed 32-bit RGBA
    /// integer) as display hints; an unreadable Color gives none.
    std::vector<ChannelHint> channels;
};

/// Whether `description` is OME-XML (holds an <OME> root element).
bool isOmeDescription(const std::string& description);

/// Parses the OME-XML `description`; throws std::runtime_error("name: reason") when the
/// <Pixels> element is missing or its sizes or DimensionOrder are invalid.
OmeMetadata parseOmeDescription(const std::string& description, const std::string& name);

/// The page layout for `pages` pages of `samplesPerPixel` samples each (an RGB page holds
/// three OME channels); throws std::runtime_error("name: reason") when it does not fit.
StackLayout omeLayout(const OmeMetadata& meta, std::size_t pages, std::size_t samplesPerPixel, const std::string& name);

}  // namespace volren::tiff
