// libFuzzer target: NIfTI-1/2 (.nii). The bytes go straight to the reader's in-memory entry
// point (readNifti on a ByteSource), the same parser the osgdb_nii plugin feeds from gzread.
#include "FuzzSupport.h"
#include "NiftiReader.h"

#include <algorithm>
#include <cstring>
#include <exception>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    volren::fuzz::silenceLogs();
    std::size_t pos = 0;
    const volren::nifti::ByteSource source = [&](void* dst, std::size_t want, std::string&) -> long long {
        const std::size_t n = std::min(want, size - pos);
        if (n) std::memcpy(dst, data + pos, n);
        pos += n;
        return static_cast<long long>(n);
    };
    try {
        volren::nifti::readNifti(source, "fuzz.nii", size);
    } catch (const std::exception&) {
    }
    return 0;
}
