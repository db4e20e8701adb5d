// libFuzzer target: OME-Zarr metadata parsing and chunk decoding. The input is
// ZARRAY + dataSeparator + ZATTRS + dataSeparator + CHUNK:
//  1. the `.zarray` and `.zattrs` parsers on their text, in memory;
//  2. the image folder fuzz.ome.zarr (.zgroup, .zattrs, 0/.zarray, and CHUNK as chunk 0 under
//     both the "." and the "/" key) opened as an OmeZarrImage; level 0's chunk 0 and a small
//     region read through ZarrArray (so a huge shape of missing chunks costs nothing); when
//     level 0 is small, the whole image read through osgDB as volren::readVolumeFile does.
#include "FuzzSupport.h"

#include <volume_model/OmeZarrImage.h>
#include <volume_model/ZarrArray.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>

namespace {

using namespace volren;

/// Reads chunk 0 and two small regions of `array`: one inside chunk 0, one across its border
/// along the last dimension (into chunk 1, usually missing: the fill value).
void readSmallParts(const ZarrArray& array)
{
    const ZarrArrayMetadata& m = array.metadata();
    if (m.chunkBytes() <= (std::uint64_t(16) << 20)) array.readChunk(std::vector<std::uint64_t>(m.shape.size(), 0));
    const std::size_t n = m.shape.size();
    ZarrBox inside{std::vector<std::uint64_t>(n, 0), std::vector<std::uint64_t>(n, 1)};
    std::uint64_t elements = 1;
    for (std::size_t d = n; d-- > 0;) {
        const std::uint64_t extent = std::min<std::uint64_t>({m.shape[d], m.chunks[d], 16});
        if (elements * extent > 4096) break;
        inside.end[d] = extent;
        elements *= extent;
    }
    array.readRegion(inside);
    ZarrBox across{std::vector<std::uint64_t>(n, 0), std::vector<std::uint64_t>(n, 1)};
    across.begin[n - 1] = m.chunks[n - 1] > 2 ? m.chunks[n - 1] - 2 : 0;
    across.end[n - 1] = std::min<std::uint64_t>(m.shape[n - 1], across.begin[n - 1] + 4);
    if (across.begin[n - 1] < across.end[n - 1]) array.readRegion(across);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    using namespace volren::fuzz;
    namespace fs = std::filesystem;
    static const bool verbose = std::getenv("VOLREN_FUZZ_VERBOSE") != nullptr;
    const auto [zarray, rest] = splitAtSeparator(data, size);
    const auto [zattrs, chunk] = splitAtSeparator(reinterpret_cast<const std::uint8_t*>(rest.data()), rest.size());
    const auto bytes = [](const std::string& s) { return reinterpret_cast<const std::uint8_t*>(s.data()); };

    silenceLogs();
    std::size_t dimensions = 0;
    try {
        dimensions = parseZarrArrayMetadata(zarray, ".zarray").shape.size();
    } catch (const std::exception&) {
    }
    try {
        parseOmeZarrAttributes(zattrs, ".zattrs");
    } catch (const std::exception&) {
    }

    const std::string group = "fuzz.ome.zarr";
    const std::string zgroup = "{\"zarr_format\": 2}";
    writeScratchFile("unused", nullptr, 0);  // empties the scratch folder
    std::error_code ec;
    fs::create_directories(scratchDir() + "/" + group + "/0", ec);
    addScratchFile(group + "/.zgroup", bytes(zgroup), zgroup.size());
    addScratchFile(group + "/.zattrs", bytes(zattrs), zattrs.size());
    addScratchFile(group + "/0/.zarray", bytes(zarray), zarray.size());
    if (dimensions > 0) {
        std::string dotted = "0", nested = "0";
        for (std::size_t d = 1; d < dimensions; ++d) {
            dotted += ".0";
            fs::create_directories(scratchDir() + "/" + group + "/0/" + nested, ec);
            nested += "/0";
        }
        addScratchFile(group + "/0/" + dotted, bytes(chunk), chunk.size());
        if (nested != dotted) addScratchFile(group + "/0/" + nested, bytes(chunk), chunk.size());
    }

    const std::string path = scratchDir() + "/" + group;
    bool small = false;
    try {
        const OmeZarrImage image(path);
        const ZarrArray& level0 = image.level(0);
        readSmallParts(level0);
        std::uint64_t chunks = 1;
        for (std::uint64_t c : level0.metadata().chunkGrid()) chunks *= c;
        small = level0.metadata().elementCount() <= (std::uint64_t(1) << 20) && chunks <= 4096;
    } catch (const std::exception& e) {
        if (verbose) std::fprintf(stderr, "volren fuzz: %s\n", e.what());
    }
    if (small) readVolumeIgnoringErrors(path);
    return 0;
}
