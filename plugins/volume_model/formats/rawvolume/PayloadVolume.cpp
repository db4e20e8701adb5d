#include "PayloadVolume.h"

#include <volume_model/LazyOpening.h>
#include <volume_model/LazyRawSource.h>

#include <osg/Notify>

#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>
#include <stdexcept>

namespace volren::rawvolume {

namespace {

/// Int32/UInt32 → float32 in place (same width); refuses values that float32 would round.
template <typename T>
void integersToFloat(std::uint8_t* data, std::size_t count, const std::string& name, const char* typeName)
{
    constexpr double limit = 16777216.0;  // 2^24: every integer up to here is exact in float32
    for (std::size_t i = 0; i < count; ++i) {
        T v;
        std::memcpy(&v, data + 4 * i, 4);
        if (std::fabs(double(v)) > limit)
            throw std::runtime_error(name + ": " + typeName + " value " + std::to_string(v) + " at voxel " + std::to_string(i) +
                                     " does not fit float32 exactly (|v| > 2^24); volren keeps " + typeName +
                                     " files as float32 only when every value fits");
        const float f = float(v);
        std::memcpy(data + 4 * i, &f, 4);
    }
}

/// Float64 -> float32 (half the width): rounded to float32's 24-bit mantissa; refuses a finite
/// value beyond float32's range (it would become infinite). NaN and infinities stay as they are.
std::vector<std::uint8_t> doublesToFloat(const std::vector<std::uint8_t>& data, std::size_t count, const std::string& name)
{
    std::vector<std::uint8_t> out(count * 4);
    for (std::size_t i = 0; i < count; ++i) {
        double v;
        std::memcpy(&v, data.data() + 8 * i, 8);
        if (std::isfinite(v) && std::fabs(v) > double(std::numeric_limits<float>::max()))
            throw std::runtime_error(name + ": float64 value " + std::to_string(v) + " at voxel " + std::to_string(i) +
                                     " is beyond float32's range (3.4e38), in which volren stores float voxels");
        const float f = float(v);
        std::memcpy(out.data() + 4 * i, &f, 4);
    }
    return out;
}

/// Voxel bytes of the layout's payload (0 when the dims or counts are not positive or overflow).
std::uint64_t payloadBytes(const PayloadLayout& layout)
{
    std::uint64_t bytes = fileVoxelSize(layout.type);
    for (const std::int64_t n : {std::int64_t(layout.dims.x()), std::int64_t(layout.dims.y()), std::int64_t(layout.dims.z()),
                                 std::int64_t(layout.channels), std::int64_t(layout.frames)}) {
        if (n <= 0 || std::uint64_t(n) > (std::uint64_t(1) << 62) / bytes) return 0;
        bytes *= std::uint64_t(n);
    }
    return bytes;
}

/// Why the payload cannot be opened lazily, or "" when it can.
std::string notLazyBecause(const PayloadLayout& layout)
{
    if (layout.parts.size() != 1) return "its voxels are split over " + std::to_string(layout.parts.size()) + " data files";
    if (layout.parts.front().compression != Compression::None) return "its voxels are compressed";
    if (layout.channels != 1 || layout.frames != 1) return "it has several channels or time points";
    if (layout.type == FileVoxelType::Int32 || layout.type == FileVoxelType::UInt32 || layout.type == FileVoxelType::Float64)
        return std::string(fileVoxelTypeName(layout.type)) + " voxels are converted to float32 when read whole";
    return {};
}

/// The payload opened lazily: a LazyRawSource over the data file, its preview level as the voxels.
osg::ref_ptr<Volume> openPayloadLazily(const PayloadLayout& layout, std::uint64_t bytes, std::uint64_t previewBudget,
                                       const osgDB::Options* options)
{
    const PayloadPart& part = layout.parts.front();
    LazyRawSource::Layout raw;
    raw.path = part.path;
    raw.offset = uncompressedPayloadStart(part, bytes, layout.name);
    raw.dims = layout.dims;
    raw.type = volumeVoxelType(layout.type);
    raw.bigEndian = layout.bigEndian;
    raw.spacing = layout.spacing;
    osg::ref_ptr<LazyRawSource> source = new LazyRawSource(raw, previewBudget, options);
    const int level = source->previewLevel();
    const osg::Vec3i dims = source->levelDims(level);
    const std::uint8_t* preview = source->residentLevel(level);
    std::vector<std::uint8_t> voxels(preview, preview + std::size_t(dims.x()) * std::size_t(dims.y()) * std::size_t(dims.z()) * voxelSize(raw.type));

    osg::ref_ptr<Volume> volume = new Volume;
    volume->assign(raw.type, dims, std::move(voxels));
    volume->setSpacing(osg::Vec3d(layout.spacing.x() * layout.dims.x() / dims.x(), layout.spacing.y() * layout.dims.y() / dims.y(),
                                  layout.spacing.z() * layout.dims.z() / dims.z()));
    volume->setRescale(layout.slope, layout.intercept);
    volume->sourceFile = layout.name;
    volume->setName(layout.name);
    volume->setFullResolution(source.get(), level);
    OSG_NOTICE << layout.name << ": opened lazily, " << layout.dims.x() << "x" << layout.dims.y() << "x" << layout.dims.z() << " "
               << voxelTypeName(raw.type) << " (" << bytes << " bytes) read on demand; level " << level << " (" << dims.x() << "x"
               << dims.y() << "x" << dims.z() << ") and coarser in memory, " << source->residentBytes() << " bytes" << std::endl;
    return volume;
}

}  // namespace

osg::ref_ptr<Volume> readPayloadVolume(const PayloadLayout& layout, const osgDB::Options* options)
{
    const std::string& name = layout.name;
    for (int a = 0; a < 3; ++a)
        if (!(layout.spacing[a] > 0.0) || !std::isfinite(layout.spacing[a]))
            throw std::runtime_error(name + ": spacing " + std::to_string(layout.spacing[a]) + " along axis " +
                                     std::to_string(a) + " is not positive and finite");
    if (!std::isfinite(layout.slope) || layout.slope == 0.0 || !std::isfinite(layout.intercept))
        throw std::runtime_error(name + ": value rescale must be finite with a non-zero slope");
    if (layout.channels <= 0 || layout.frames <= 0)
        throw std::runtime_error(name + ": channel count " + std::to_string(layout.channels) + " and time point count " +
                                 std::to_string(layout.frames) + " must be positive");
    const LazyOpening lazy = lazyOpeningOf(options);
    // Lazily also when the volume is over what a Volume holds (the whole read would be refused).
    const std::uint64_t payload = payloadBytes(layout), payloadVoxels = payload / fileVoxelSize(layout.type);
    if (payload > 0 && payloadVoxels <= LazyRawSource::maxVoxels && (lazy.opensLazily(payload) || payloadVoxels > Volume::maxVoxels)) {
        const std::string why = notLazyBecause(layout);
        if (why.empty()) {
            osg::ref_ptr<Volume> volume = openPayloadLazily(layout, payload, lazy.previewBudget(), options);
            if (layout.type == FileVoxelType::Float32)
                if (const auto bad = volume->nonFiniteCount())
                    OSG_WARN << name << ": " << bad << " NaN/Inf voxels in the preview level; they are treated as empty" << std::endl;
            return volume;
        }
        OSG_NOTICE << name << ": read whole, not lazily: " << why << std::endl;
    }
    std::uint64_t count = 0;
    try {
        count = Volume::checkedVoxelCount(layout.dims, std::uint64_t(layout.channels) * std::uint64_t(layout.frames));
    } catch (const std::exception& e) {
        throw std::runtime_error(name + ": " + e.what());
    }
    std::size_t width = fileVoxelSize(layout.type);
    const std::uint64_t bytes = count * width;

    checkPayloadFits(layout.parts, bytes, name);
    std::vector<std::uint8_t> voxels;
    try {
        voxels.resize(std::size_t(bytes));
    } catch (const std::bad_alloc&) {
        throw std::runtime_error(name + ": not enough memory for " + std::to_string(count) + " voxels");
    }
    readPayload(layout.parts, voxels.data(), bytes, name, options);
    if (layout.bigEndian != (std::endian::native == std::endian::big)) swapBytes(voxels.data(), std::size_t(count), width);
    if (layout.type == FileVoxelType::Int32) integersToFloat<std::int32_t>(voxels.data(), std::size_t(count), name, "int32");
    if (layout.type == FileVoxelType::UInt32) integersToFloat<std::uint32_t>(voxels.data(), std::size_t(count), name, "uint32");
    if (layout.type == FileVoxelType::Float64) {
        voxels = doublesToFloat(voxels, std::size_t(count), name);
        width = 4;
    }

    if (layout.channels > 1) {
        // The file interleaves channels per voxel; the Volume keeps one block per channel.
        std::vector<std::uint8_t> planar(voxels.size());
        const std::size_t n = std::size_t(count) / std::size_t(layout.channels) / std::size_t(layout.frames);
        const std::size_t c = std::size_t(layout.channels);
        for (std::size_t t = 0; t < std::size_t(layout.frames); ++t)
            for (std::size_t ch = 0; ch < c; ++ch) {
                std::uint8_t* out = planar.data() + ((t * c + ch) * n) * width;
                const std::uint8_t* in = voxels.data() + (t * n * c + ch) * width;
                for (std::size_t v = 0; v < n; ++v) std::memcpy(out + v * width, in + v * c * width, width);
            }
        voxels.swap(planar);
    }

    osg::ref_ptr<Volume> volume = new Volume;
    volume->assign(volumeVoxelType(layout.type), layout.dims, std::move(voxels), layout.channels, layout.frames);
    volume->setSpacing(layout.spacing);
    volume->setRescale(layout.slope, layout.intercept);
    volume->sourceFile = name;
    volume->setName(name);
    if (layout.type == FileVoxelType::Int32 || layout.type == FileVoxelType::UInt32)
        OSG_NOTICE << name << ": " << fileVoxelTypeName(layout.type) << " voxels stored as float32 (all values exact)" << std::endl;
    if (layout.type == FileVoxelType::Float64)
        OSG_NOTICE << name << ": float64 voxels stored as float32 (rounded to 24 significant bits)" << std::endl;
    if (layout.type == FileVoxelType::Float32 || layout.type == FileVoxelType::Float64)
        if (const auto bad = volume->nonFiniteCount())
            OSG_WARN << name << ": " << bad << " NaN/Inf voxels; they are treated as empty" << std::endl;
    return volume;
}

}  // namespace volren::rawvolume
