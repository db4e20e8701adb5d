#include "NiftiByteSource.h"

#include <algorithm>
#include <cstdint>
#include <stdexcept>

namespace volren::nifti {

void readExactly(const ByteSource& source, void* dst, std::size_t size, const std::string& name, const char* what)
{
    std::size_t done = 0;
    auto* out = static_cast<std::uint8_t*>(dst);
    while (done < size) {
        const std::size_t chunk = std::min<std::size_t>(size - done, std::size_t(1) << 30);
        std::string error;
        const long long got = source(out + done, chunk, error);
        if (got < 0) throw std::runtime_error(name + ": " + what + ": " + error);
        if (got == 0)
            throw std::runtime_error(name + ": truncated: " + what + " needs " + std::to_string(size) +
                                     " bytes, file ends after " + std::to_string(done));
        done += std::size_t(got);
    }
}

}  // namespace volren::nifti
