#pragma once
#include <volume_model/Volume.h>

#include <cstdint>
#include <string>
#include <vector>

namespace volren::tiff {

/// ImageJ's private TIFF tags that hold its IJMetadata: the byte count of each entry, then the
/// entries themselves.
constexpr unsigned int imageJMetadataCountsTag = 50838;
constexpr unsigned int imageJMetadataTag = 50839;

/// How ImageJ shows each of `channels` channels, from IJMetadata (`counts`: tag 50838, `data`:
/// tag 50839): the lookup table ("luts", 256 reds, greens, blues) and display range ("rang",
/// minimum and maximum per channel) where the file has them. Display hints are optional: a
/// malformed block gives no hints and a warning naming `name`, never an error.
std::vector<ChannelHint> parseImageJDisplay(const std::vector<std::uint32_t>& counts, const std::vector<std::uint8_t>& data,
                                            std::size_t channels, const std::string& name);

}  // namespace volren::tiff
