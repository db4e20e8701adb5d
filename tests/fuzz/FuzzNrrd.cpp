// libFuzzer target: NRRD through the osgDB reader. fuzz_nrrd writes the input as one attached
// .nrrd file; fuzz_nhdr splits it at dataSeparator into a detached .nhdr header and the data
// files "data.raw" and "data1.raw" beside it (seeds name that file in their "data file:" field).
#include "FuzzSupport.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    using namespace volren::fuzz;
    const std::string ext = VOLREN_FUZZ_EXT;
    if (ext == "nrrd") {
        readVolumeIgnoringErrors(writeScratchFile("fuzz.nrrd", data, size));
    } else {
        const auto [header, payload] = splitAtSeparator(data, size);
        const std::string path =
            writeScratchFile("fuzz.nhdr", reinterpret_cast<const std::uint8_t*>(header.data()), header.size());
        const auto* bytes = reinterpret_cast<const std::uint8_t*>(payload.data());
        addScratchFile("data.raw", bytes, payload.size());
        addScratchFile("data1.raw", bytes, payload.size());  // for "data%d.raw 1 1 1" patterns
        readVolumeIgnoringErrors(path);
    }
    return 0;
}
