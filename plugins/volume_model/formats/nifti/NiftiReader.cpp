#include "NiftiReader.h"

#include <osg/Notify>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>

namespace volren::nifti {

namespace {

constexpr std::size_t headerSize = 348;

/// NIfTI-1 datatype codes (nifti1.h).
enum DataType : int {
    DT_UINT8 = 2, DT_INT16 = 4, DT_INT32 = 8, DT_FLOAT32 = 16, DT_FLOAT64 = 64,
    DT_INT8 = 256, DT_UINT16 = 512, DT_UINT32 = 768, DT_INT64 = 1024, DT_UINT64 = 1280,
};

struct Header
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

void swapInPlace(std::uint8_t* data, std::size_t count, std::size_t width)
{
    for (std::size_t i = 0; i < count; ++i) std::reverse(data + i * width, data + (i + 1) * width);
}

std::string dataTypeName(int code)
{
    switch (code) {
    case 1: return "binary (1 bit)";
    case DT_INT32: return "int32";
    case DT_UINT32: return "uint32";
    case DT_FLOAT64: return "float64";
    case DT_INT64: return "int64";
    case DT_UINT64: return "uint64";
    case 32: return "complex64";
    case 128: return "RGB24";
    case 1536: return "float128";
    case 1792: return "complex128";
    case 2048: return "complex256";
    case 2304: return "RGBA32";
    default: return "code " + std::to_string(code);
    }
}

/// Reads exactly `size` bytes or throws with a truncation message.
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

template <typename T>
void widenToFloat(const std::vector<std::uint8_t>& in, std::vector<std::uint8_t>& out, std::size_t count)
{
    out.resize(count * sizeof(float));
    for (std::size_t i = 0; i < count; ++i) {
        T v;
        std::memcpy(&v, in.data() + i * sizeof(T), sizeof(T));
        const float f = float(v);
        std::memcpy(out.data() + i * sizeof(float), &f, sizeof(float));
    }
}

}  // namespace

osg::ref_ptr<Volume> readNifti1(const ByteSource& source, const std::string& name)
{
    std::uint8_t raw[headerSize];
    readExactly(source, raw, headerSize, name, "NIfTI header");

    Header h{raw, false};
    const std::int32_t sizeofHdr = h.get<std::int32_t>(0);
    if (sizeofHdr != 348) {
        h.swap = true;
        if (h.get<std::int32_t>(0) != 348) {
            if (sizeofHdr == 540 || h.get<std::int32_t>(0) == 540)
                throw std::runtime_error(name + ": NIfTI-2 files are not supported yet (only NIfTI-1)");
            throw std::runtime_error(name + ": not a NIfTI-1 file (sizeof_hdr is " + std::to_string(sizeofHdr) +
                                     ", expected 348)");
        }
    }
    const char* magic = reinterpret_cast<const char*>(raw + 344);
    if (std::memcmp(magic, "ni1\0", 4) == 0)
        throw std::runtime_error(name + ": two-file NIfTI (.hdr/.img pair) is not supported; use a single .nii");
    if (std::memcmp(magic, "n+1\0", 4) != 0) throw std::runtime_error(name + ": bad NIfTI-1 magic (expected 'n+1')");

    // Dimensions: dim[0] is the rank; missing spatial axes count as 1.
    const int rank = h.get<std::int16_t>(40);
    if (rank < 1 || rank > 7) throw std::runtime_error(name + ": invalid dim[0] = " + std::to_string(rank) + " (must be 1..7)");
    int dim[8] = {rank, 1, 1, 1, 1, 1, 1, 1};
    for (int i = 1; i <= rank; ++i) {
        dim[i] = h.get<std::int16_t>(40 + 2 * i);
        if (dim[i] <= 0)
            throw std::runtime_error(name + ": dim[" + std::to_string(i) + "] = " + std::to_string(dim[i]) +
                                     " is not positive");
    }
    std::uint64_t volumes = 1;
    for (int i = 4; i <= rank; ++i) volumes *= std::uint64_t(dim[i]);

    const int datatype = h.get<std::int16_t>(70);
    VoxelType stored;
    std::size_t fileVoxelSize = 0;
    switch (datatype) {
    case DT_UINT8: stored = VoxelType::UInt8; fileVoxelSize = 1; break;
    case DT_INT8: stored = VoxelType::Int8; fileVoxelSize = 1; break;
    case DT_UINT16: stored = VoxelType::UInt16; fileVoxelSize = 2; break;
    case DT_INT16: stored = VoxelType::Int16; fileVoxelSize = 2; break;
    case DT_FLOAT32: stored = VoxelType::Float32; fileVoxelSize = 4; break;
    case DT_INT32: case DT_UINT32: stored = VoxelType::Float32; fileVoxelSize = 4; break;
    case DT_FLOAT64: case DT_INT64: case DT_UINT64: stored = VoxelType::Float32; fileVoxelSize = 8; break;
    default: throw std::runtime_error(name + ": unsupported NIfTI datatype " + dataTypeName(datatype));
    }

    osg::Vec3d spacing;
    for (int a = 0; a < 3; ++a) {
        const double p = std::fabs(double(h.get<float>(76 + 4 * (a + 1))));
        if (!(p > 0.0) || !std::isfinite(p)) {
            OSG_WARN << name << ": pixdim[" << a + 1 << "] = " << p << " is not a positive spacing; using 1" << std::endl;
            spacing[a] = 1.0;
        } else {
            spacing[a] = p;
        }
    }

    const double voxOffset = h.get<float>(108);
    if (!(voxOffset >= double(headerSize)) || voxOffset > double(1u << 30) || voxOffset != std::floor(voxOffset))
        throw std::runtime_error(name + ": invalid vox_offset " + std::to_string(voxOffset));

    double slope = h.get<float>(112), intercept = h.get<float>(116);
    if (!std::isfinite(slope) || slope == 0.0) slope = 1.0, intercept = 0.0;  // spec: 0 means unscaled
    if (!std::isfinite(intercept)) intercept = 0.0;

    const osg::Vec3i dims(dim[1], dim[2], dim[3]);
    std::uint64_t count = 0;
    try {
        count = Volume::checkedVoxelCount(dims);
    } catch (const std::exception& e) {
        throw std::runtime_error(name + ": " + e.what());
    }
    if (volumes > 1)
        OSG_WARN << name << ": file holds " << volumes << " volumes (dims 4..7); volren reads the first" << std::endl;

    // Skip extensions between the header and the voxels.
    std::size_t skip = std::size_t(voxOffset) - headerSize;
    std::vector<std::uint8_t> scratch(std::min<std::size_t>(skip, 1 << 16));
    while (skip > 0) {
        const std::size_t n = std::min(skip, scratch.size());
        readExactly(source, scratch.data(), n, name, "NIfTI extension block");
        skip -= n;
    }

    std::vector<std::uint8_t> bytes;
    try {
        bytes.resize(std::size_t(count) * fileVoxelSize);
    } catch (const std::bad_alloc&) {
        throw std::runtime_error(name + ": not enough memory for " + std::to_string(count) + " voxels");
    }
    readExactly(source, bytes.data(), bytes.size(), name, "voxel data");
    if (h.swap && fileVoxelSize > 1) swapInPlace(bytes.data(), std::size_t(count), fileVoxelSize);

    if (stored == VoxelType::Float32 && datatype != DT_FLOAT32) {
        std::vector<std::uint8_t> widened;
        switch (datatype) {
        case DT_INT32: widenToFloat<std::int32_t>(bytes, widened, count); break;
        case DT_UINT32: widenToFloat<std::uint32_t>(bytes, widened, count); break;
        case DT_FLOAT64: widenToFloat<double>(bytes, widened, count); break;
        case DT_INT64: widenToFloat<std::int64_t>(bytes, widened, count); break;
        case DT_UINT64: widenToFloat<std::uint64_t>(bytes, widened, count); break;
        default: break;
        }
        OSG_NOTICE << name << ": " << dataTypeName(datatype) << " voxels stored as float32" << std::endl;
        bytes.swap(widened);
    }

    osg::ref_ptr<Volume> volume = new Volume;
    volume->assign(stored, dims, std::move(bytes));
    volume->setSpacing(spacing);
    volume->setRescale(slope, intercept);
    volume->sourceFile = name;
    volume->setName(name);
    if (const auto bad = volume->nonFiniteCount())
        OSG_WARN << name << ": " << bad << " NaN/Inf voxels; they are treated as empty" << std::endl;
    return volume;
}

}  // namespace volren::nifti
