#include "ImageJDisplay.h"

#include <osg/Notify>

#include <cmath>
#include <cstring>
#include <stdexcept>

namespace volren::tiff {

namespace {

/// Reads big- or little-endian numbers from a byte block, refusing to read past its end.
struct Reader
{
    const std::vector<std::uint8_t>& bytes;
    bool bigEndian = true;

    std::uint64_t unsignedAt(std::size_t at, std::size_t size) const
    {
        if (at > bytes.size() || size > bytes.size() - at) throw std::runtime_error("an entry runs past the metadata's end");
        std::uint64_t v = 0;
        for (std::size_t i = 0; i < size; ++i)
            v |= std::uint64_t(bytes[at + (bigEndian ? i : size - 1 - i)]) << (8 * (size - 1 - i));
        return v;
    }
    double doubleAt(std::size_t at) const
    {
        const std::uint64_t bits = unsignedAt(at, 8);
        double v = 0.0;
        std::memcpy(&v, &bits, sizeof v);
        return v;
    }
};

std::vector<ChannelHint> parse(const std::vector<std::uint32_t>& counts, const std::vector<std::uint8_t>& data,
                               std::size_t channels)
{
    if (counts.empty() || data.size() < 4) throw std::runtime_error("no header");
    Reader in{data};
    const std::string magic(data.begin(), data.begin() + 4);
    if (magic == "JIJI") in.bigEndian = false;
    else if (magic != "IJIJ") throw std::runtime_error("the header does not start with IJIJ");
    const std::size_t header = counts[0];
    if (header < 4 || (header - 4) % 8 != 0 || header > data.size()) throw std::runtime_error("a bad header size");
    std::vector<ChannelHint> hints(channels);
    std::size_t at = header, entry = 1;
    for (std::size_t h = 4; h < header; h += 8) {
        // The type is a 4-character code stored as an int: reversed in a little-endian block.
        std::string type(data.begin() + std::ptrdiff_t(h), data.begin() + std::ptrdiff_t(h + 4));
        if (!in.bigEndian) type.assign(type.rbegin(), type.rend());
        const std::uint64_t n = in.unsignedAt(h + 4, 4);
        for (std::uint64_t k = 0; k < n; ++k, ++entry) {
            if (entry >= counts.size()) throw std::runtime_error("more entries than byte counts");
            const std::size_t size = counts[entry];
            if (at > data.size() || size > data.size() - at) throw std::runtime_error("an entry runs past the metadata's end");
            if (type == "rang") {  // min, max per channel
                for (std::size_t c = 0; c < channels && 16 * (c + 1) <= size; ++c) {
                    const double low = in.doubleAt(at + 16 * c), high = in.doubleAt(at + 16 * c + 8);
                    if (!(high > low) || !std::isfinite(low) || !std::isfinite(high)) continue;
                    hints[c].hasWindow = true;
                    hints[c].low = low;
                    hints[c].high = high;
                }
            } else if (type == "luts" && k < channels && size == 768) {  // 256 reds, greens, blues
                std::vector<osg::Vec3f>& colours = hints[std::size_t(k)].colours;
                for (std::size_t i = 0; i < 256; ++i)
                    colours.emplace_back(data[at + i] / 255.0f, data[at + 256 + i] / 255.0f, data[at + 512 + i] / 255.0f);
            }
            at += size;
        }
    }
    return hints;
}

}  // namespace

std::vector<ChannelHint> parseImageJDisplay(const std::vector<std::uint32_t>& counts, const std::vector<std::uint8_t>& data,
                                            std::size_t channels, const std::string& name)
{
    try {
        return parse(counts, data, channels);
    } catch (const std::exception& e) {
        OSG_WARN << name << ": ImageJ display metadata (tags 50838/50839) ignored: " << e.what() << std::endl;
        return {};
    }
}

}  // namespace volren::tiff
