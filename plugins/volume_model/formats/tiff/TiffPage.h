#pragma once
#include "TiffFile.h"

#include <volume_model/VoxelType.h>

#include <cstdint>
#include <string>
#include <vector>

namespace volren::tiff {

/// What one TIFF page (directory) holds, as far as stacking pages into a volume cares.
struct PageFormat
{
    std::uint32_t width = 0, height = 0;
    std::uint16_t bitsPerSample = 0, samplesPerPixel = 1, sampleFormat = SAMPLEFORMAT_UINT;
    std::uint16_t planar = PLANARCONFIG_CONTIG, photometric = PHOTOMETRIC_MINISBLACK, compression = COMPRESSION_NONE;
    bool tiled = false;
    VoxelType type = VoxelType::UInt8;  ///< stored type in the volume
    bool widenToFloat = false;          ///< 32-bit integers, stored as float32

    /// "WxH, N-bit <format> x S samples" for messages.
    std::string describe() const;
    /// Whether pages `a` and `b` stack into one volume (size, samples and type agree).
    bool sameLayout(const PageFormat& other) const;
};

/// Format of the current page of `file`; throws std::runtime_error naming the file, the page
/// (`page`, counted from 0, for messages) and the reason for unsupported pages.
PageFormat readPageFormat(TiffFile& file, std::size_t page);

/// Checks that the current page's strips or tiles lie inside the file (a truncated file
/// fails here, before any decoding); throws std::runtime_error otherwise.
void checkPageExtent(TiffFile& file, const PageFormat& format, std::size_t page);

/// Decodes the current page into `planes`: samplesPerPixel planes of width*height samples
/// of voxelSize(format.type) bytes each, one after the other. Throws on decoding errors.
void readPageSamples(TiffFile& file, const PageFormat& format, std::size_t page, std::vector<std::uint8_t>& planes);

}  // namespace volren::tiff
