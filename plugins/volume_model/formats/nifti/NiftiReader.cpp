#include "NiftiReader.h"
#include "NiftiHeader.h"
#include "NiftiOrientation.h"

#include <volume_model/LengthUnit.h>

#include <osg/Notify>
#include <osg/ValueObject>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>

namespace volren::nifti {

namespace {

/// NIfTI datatype codes (nifti1.h, nifti2.h).
enum DataType : int {
    DT_UINT8 = 2, DT_INT16 = 4, DT_INT32 = 8, DT_FLOAT32 = 16, DT_FLOAT64 = 64,
    DT_INT8 = 256, DT_UINT16 = 512, DT_UINT32 = 768, DT_INT64 = 1024, DT_UINT64 = 1280,
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

osg::ref_ptr<Volume> readNifti(const ByteSource& source, const std::string& name, std::uint64_t maxBytes)
{
    const NiftiHeader h = readNiftiHeader(source, name);
    const std::int64_t rank = h.dim[0];
    for (int i = 1; i <= 3; ++i)
        if (h.dim[i] > std::numeric_limits<int>::max())
            throw std::runtime_error(name + ": dim[" + std::to_string(i) + "] = " + std::to_string(h.dim[i]) +
                                     " is too large");
    double volumes = 1;
    for (int i = 4; i <= rank; ++i) volumes *= double(h.dim[i]);

    const int datatype = h.datatype;
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
        const double p = std::fabs(h.pixdim[a + 1]);
        if (!(p > 0.0) || !std::isfinite(p)) {
            OSG_WARN << name << ": pixdim[" << a + 1 << "] = " << p << " is not a positive spacing; using 1" << std::endl;
            spacing[a] = 1.0;
        } else {
            spacing[a] = p;
        }
    }

    const double voxOffset = h.voxOffset;
    if (!(voxOffset >= double(h.size)) || voxOffset > double(1u << 30) || voxOffset != std::floor(voxOffset))
        throw std::runtime_error(name + ": invalid vox_offset " + std::to_string(voxOffset));

    double slope = h.slope, intercept = h.intercept;
    if (!std::isfinite(slope) || slope == 0.0) slope = 1.0, intercept = 0.0;  // spec: 0 means unscaled
    if (!std::isfinite(intercept)) intercept = 0.0;

    const osg::Vec3i dims(int(h.dim[1]), int(h.dim[2]), int(h.dim[3]));
    std::uint64_t count = 0;
    try {
        count = Volume::checkedVoxelCount(dims);
    } catch (const std::exception& e) {
        throw std::runtime_error(name + ": " + e.what());
    }
    // A few header bytes can claim gigabytes: check them against the source before allocating.
    const std::uint64_t voxelBytes = count * fileVoxelSize;
    if (voxelBytes > maxBytes || std::uint64_t(voxOffset) > maxBytes - voxelBytes)
        throw std::runtime_error(name + ": truncated: voxel data needs " + std::to_string(voxelBytes) + " bytes from byte " +
                                 std::to_string(std::uint64_t(voxOffset)) + ", the file can hold at most " +
                                 std::to_string(maxBytes) + " bytes");
    if (volumes > 1)
        OSG_WARN << name << ": file holds " << volumes << " volumes (dims 4..7); volren reads the first" << std::endl;

    // Skip extensions between the header and the voxels.
    std::size_t skip = std::size_t(voxOffset) - h.size;
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
    if (h.swapped && fileVoxelSize > 1) swapInPlace(bytes.data(), std::size_t(count), fileVoxelSize);

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
    if (const std::string unit = spatialUnit(h); !unit.empty()) volume->setUserValue(spacingUnitKey, unit);
    volume->setRescale(slope, intercept);
    volume->sourceFile = name;
    volume->setName(name);
    std::string orientationSource;
    volume->setUserValue(voxelToWorldKey, voxelToWorld(h, orientationSource));
    volume->setUserValue(voxelToWorldSourceKey, orientationSource);
    if (const auto bad = volume->nonFiniteCount())
        OSG_WARN << name << ": " << bad << " NaN/Inf voxels; they are treated as empty" << std::endl;
    return volume;
}

}  // namespace volren::nifti
