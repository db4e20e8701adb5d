// libFuzzer target: headerless .raw with its sidecar (fuzz_raw) and QVis .dat (fuzz_dat)
// through the osgDB reader. The input is split at dataSeparator: fuzz_raw writes the text
// before it as fuzz.raw.txt and the bytes after it as fuzz.raw; fuzz_dat writes the header as
// fuzz.dat and the bytes as "data.raw" (seeds name that file in ObjectFileName).
#include "FuzzSupport.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    using namespace volren::fuzz;
    const std::string ext = VOLREN_FUZZ_EXT;
    const auto [header, payload] = splitAtSeparator(data, size);
    const auto* h = reinterpret_cast<const std::uint8_t*>(header.data());
    const auto* p = reinterpret_cast<const std::uint8_t*>(payload.data());
    if (ext == "raw") {
        writeScratchFile("fuzz.raw.txt", h, header.size());
        readVolumeIgnoringErrors(addScratchFile("fuzz.raw", p, payload.size()));
    } else {
        const std::string path = writeScratchFile("fuzz.dat", h, header.size());
        addScratchFile("data.raw", p, payload.size());
        readVolumeIgnoringErrors(path);
    }
    return 0;
}
