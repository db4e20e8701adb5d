#include "NiftiHeader.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>

namespace volren::nifti {

namespace {

constexpr std::size_t nifti1Size = 348, nifti2Size = 540;

/// Typed access to the raw header bytes in file byte order.
struct RawHeader
{
    const std::uint8_t* bytes;
    bool swap;

    template <typename T>
    T get(std::size_t offset) const
    {
        T v;
        std::memcpy(&v, bytes + offset, sizeof(T));
        if (swap) {
            auto* p = reinterpret_cast<std::uint8_t*>(&v);
            std::reverse(p, p + sizeof(T));
        }
        return v;
    }
};

void parseNifti1(const RawHeader& r, NiftiHeader& h, const std::string& name)
{
    const char* magic = reinterpret_cast<const char*>(r.bytes + 344);
    if (std::memcmp(magic, "ni1\0", 4) == 0)
        throw std::runtime_error(name + ": two-file NIfTI (.hdr/.img pair) is not supported; use a single .nii");
    if (std::memcmp(magic, "n+1\0", 4) != 0) throw std::runtime_error(name + ": bad NIfTI-1 magic (expected 'n+1')");
    for (int i = 0; i < 8; ++i) h.dim[i] = r.get<std::int16_t>(40 + 2 * i);
    h.datatype = r.get<std::int16_t>(70);
    for (int i = 0; i < 8; ++i) h.pixdim[i] = r.get<float>(76 + 4 * i);
    h.voxOffset = r.get<float>(108);
    h.slope = r.get<float>(112);
    h.intercept = r.get<float>(116);
    h.qformCode = r.get<std::int16_t>(252);
    h.sformCode = r.get<std::int16_t>(254);
    for (int i = 0; i < 3; ++i) h.quatern[i] = r.get<float>(256 + 4 * i);
    for (int i = 0; i < 3; ++i) h.qoffset[i] = r.get<float>(268 + 4 * i);
    for (int row = 0; row < 3; ++row)
        for (int c = 0; c < 4; ++c) h.srow[row][c] = r.get<float>(280 + 16 * row + 4 * c);
    h.xyztUnits = r.get<std::uint8_t>(123);
}

void parseNifti2(const RawHeader& r, NiftiHeader& h, const std::string& name)
{
    const char* magic = reinterpret_cast<const char*>(r.bytes + 4);
    if (std::memcmp(magic, "ni2\0", 4) == 0)
        throw std::runtime_error(name + ": two-file NIfTI-2 (.hdr/.img pair) is not supported; use a single .nii");
    if (std::memcmp(magic, "n+2\0", 4) != 0) throw std::runtime_error(name + ": bad NIfTI-2 magic (expected 'n+2')");
    if (std::memcmp(magic + 4, "\r\n\032\n", 4) != 0)
        throw std::runtime_error(name + ": NIfTI-2 magic is damaged (file transferred in text mode?)");
    h.datatype = r.get<std::int16_t>(12);
    for (int i = 0; i < 8; ++i) h.dim[i] = r.get<std::int64_t>(16 + 8 * i);
    for (int i = 0; i < 8; ++i) h.pixdim[i] = r.get<double>(104 + 8 * i);
    const std::int64_t offset = r.get<std::int64_t>(168);
    h.voxOffset = double(offset);
    h.slope = r.get<double>(176);
    h.intercept = r.get<double>(184);
    h.qformCode = r.get<std::int32_t>(344);
    h.sformCode = r.get<std::int32_t>(348);
    for (int i = 0; i < 3; ++i) h.quatern[i] = r.get<double>(352 + 8 * i);
    for (int i = 0; i < 3; ++i) h.qoffset[i] = r.get<double>(376 + 8 * i);
    for (int row = 0; row < 3; ++row)
        for (int c = 0; c < 4; ++c) h.srow[row][c] = r.get<double>(400 + 32 * row + 8 * c);
    h.xyztUnits = r.get<std::int32_t>(500);
}

}  // namespace

NiftiHeader readNiftiHeader(const ByteSource& source, const std::string& name)
{
    std::uint8_t raw[nifti2Size];
    readExactly(source, raw, nifti1Size, name, "NIfTI header");

    RawHeader r{raw, false};
    NiftiHeader h;
    const std::int32_t sizeofHdr = r.get<std::int32_t>(0);
    r.swap = true;
    const std::int32_t swappedSize = r.get<std::int32_t>(0);
    if (sizeofHdr == std::int32_t(nifti1Size) || sizeofHdr == std::int32_t(nifti2Size)) r.swap = false;
    else if (swappedSize != std::int32_t(nifti1Size) && swappedSize != std::int32_t(nifti2Size))
        throw std::runtime_error(name + ": not a NIfTI-1 file nor NIfTI-2 (sizeof_hdr is " + std::to_string(sizeofHdr) +
                                 ", expected 348, or 540 for NIfTI-2)");
    h.swapped = r.swap;
    if (r.get<std::int32_t>(0) == std::int32_t(nifti2Size)) {
        readExactly(source, raw + nifti1Size, nifti2Size - nifti1Size, name, "NIfTI-2 header");
        h.version = 2;
        h.size = nifti2Size;
        parseNifti2(r, h, name);
    } else {
        parseNifti1(r, h, name);
    }

    const std::int64_t rank = h.dim[0];
    if (rank < 1 || rank > 7)
        throw std::runtime_error(name + ": invalid dim[0] = " + std::to_string(rank) + " (must be 1..7)");
    for (std::int64_t i = rank + 1; i < 8; ++i) h.dim[i] = 1;  // missing axes count as 1
    for (int i = 1; i <= rank; ++i)
        if (h.dim[i] <= 0)
            throw std::runtime_error(name + ": dim[" + std::to_string(i) + "] = " + std::to_string(h.dim[i]) +
                                     " is not positive");
    return h;
}

std::string spatialUnit(const NiftiHeader& header)
{
    switch (header.xyztUnits & 0x07) {
    case 1: return "m";
    case 2: return "mm";
    case 3: return "\xC2\xB5m";
    default: return {};
    }
}

}  // namespace volren::nifti
