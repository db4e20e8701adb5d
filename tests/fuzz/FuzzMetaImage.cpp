// libFuzzer target: MetaImage through the osgDB reader. fuzz_mha writes the input as one attached
// .mha file; fuzz_mhd splits it at dataSeparator into a detached .mhd header and the
// data files "data.raw" and "data1.raw" beside it (seeds name that file in ElementDataFile).
#include "FuzzSupport.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    using namespace volren::fuzz;
    const std::string ext = VOLREN_FUZZ_EXT;
    if (ext == "mha") {
        readVolumeIgnoringErrors(writeScratchFile("fuzz.mha", data, size));
    } else {
        const auto [header, payload] = splitAtSeparator(data, size);
        const std::string path =
            writeScratchFile("fuzz.mhd", reinterpret_cast<const std::uint8_t*>(header.data()), header.size());
        const auto* bytes = reinterpret_cast<const std::uint8_t*>(payload.data());
        addScratchFile("data.raw", bytes, payload.size());
        addScratchFile("data1.raw", bytes, payload.size());  // for "data%d.raw 1 1 1" patterns
        readVolumeIgnoringErrors(path);
    }
    return 0;
}
