// A volume's mip levels, built on the CPU in separable passes (x, then y, then z per level), so
// NaN voxels and odd sizes follow one rule on every driver.
#include <volume_renderer/VolumeMipChain.h>
#include <volume_renderer/VolumeTextures.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

namespace volren {

osg::Vec3i mipDims(const osg::Vec3i& dims, int level)
{
    return {std::max(1, dims.x() >> level), std::max(1, dims.y() >> level), std::max(1, dims.z() >> level)};
}

int mipLevelCount(const osg::Vec3i& dims)
{
    int levels = 1;
    while (mipDims(dims, levels - 1) != osg::Vec3i(1, 1, 1)) ++levels;
    return levels;
}

double mipVoxelSpan(const osg::Vec3i& dims, int level)
{
    const osg::Vec3i d = mipDims(dims, level);
    return std::max({double(dims.x()) / d.x(), double(dims.y()) / d.y(), double(dims.z()) / d.z()});
}

namespace {

/// Values of a level, x fastest.
struct Level
{
    osg::Vec3i dims;
    std::vector<float> values;
};

/// `in` reduced along `axis` to `size` voxels: voxel j averages the input over its box
/// [j r, (j+1) r), r = n / size, weighting each input voxel by its overlap; NaN left out.
Level reduce(const Level& in, int axis, int size)
{
    const int n = in.dims[axis];
    Level out{in.dims, {}};
    out.dims[axis] = size;
    out.values.resize(std::size_t(out.dims.x()) * out.dims.y() * out.dims.z());
    const std::size_t stride = axis == 0 ? 1 : axis == 1 ? std::size_t(in.dims.x()) : std::size_t(in.dims.x()) * in.dims.y();
    const double r = double(n) / size;
    // Per output index: the input voxels it covers and their weights (the same for every line).
    std::vector<std::vector<std::pair<int, double>>> taps(static_cast<std::size_t>(size));
    for (int j = 0; j < size; ++j) {
        const double a = j * r, b = (j + 1) * r;
        for (int i = int(std::floor(a)); i < std::min(n, int(std::ceil(b))); ++i) {
            const double w = std::min(b, i + 1.0) - std::max(a, double(i));
            if (w > 0.0) taps[std::size_t(j)].emplace_back(i, w);
        }
    }
    const osg::Vec3i o = out.dims;
    for (int z = 0; z < o.z(); ++z)
        for (int y = 0; y < o.y(); ++y)
            for (int x = 0; x < o.x(); ++x) {
                const int coords[3] = {x, y, z};
                osg::Vec3i first(x, y, z);
                first[axis] = 0;
                const std::size_t base = std::size_t(first.x()) + std::size_t(in.dims.x()) * (std::size_t(first.y()) + std::size_t(in.dims.y()) * first.z());
                double sum = 0.0, weight = 0.0;
                for (const auto& [i, w] : taps[std::size_t(coords[axis])]) {
                    const float v = in.values[base + std::size_t(i) * stride];
                    if (std::isnan(v)) continue;
                    sum += w * double(v);
                    weight += w;
                }
                out.values[std::size_t(x) + std::size_t(o.x()) * (std::size_t(y) + std::size_t(o.y()) * z)] =
                    weight > 0.0 ? float(sum / weight) : std::numeric_limits<float>::quiet_NaN();
            }
    return out;
}

template <typename T>
void store(const std::vector<float>& values, std::uint8_t* out)
{
    for (std::size_t i = 0; i < values.size(); ++i) {
        T v;
        if constexpr (std::is_floating_point_v<T>) {
            v = T(values[i]);
        } else {
            const double clamped = std::clamp(std::round(double(values[i])), double(std::numeric_limits<T>::min()),
                                              double(std::numeric_limits<T>::max()));
            v = T(clamped);
        }
        std::memcpy(out + i * sizeof(T), &v, sizeof(T));
    }
}

void storeAs(VoxelType type, const std::vector<float>& values, std::uint8_t* out)
{
    switch (type) {
    case VoxelType::UInt8: store<std::uint8_t>(values, out); break;
    case VoxelType::Int8: store<std::int8_t>(values, out); break;
    case VoxelType::UInt16: store<std::uint16_t>(values, out); break;
    case VoxelType::Int16: store<std::int16_t>(values, out); break;
    case VoxelType::Float32: store<float>(values, out); break;
    }
}

}  // namespace

std::vector<osg::ref_ptr<osg::Image>> mipLevelImages(const Volume& volume, int levels)
{
    const osg::Vec3i d0 = volume.dims();
    levels = std::clamp(levels, 0, mipLevelCount(d0) - 1);
    const std::size_t voxelBytes = volume.byteSize() / volume.totalVoxelCount();
    std::vector<osg::ref_ptr<osg::Image>> out;
    if (levels == 0) return out;
    Level level{d0, std::vector<float>(volume.voxelCount())};
    for (std::size_t i = 0; i < level.values.size(); ++i) level.values[i] = float(volume.storedValue(i));
    for (int l = 1; l <= levels; ++l) {
        const osg::Vec3i d = mipDims(d0, l);
        for (int axis = 0; axis < 3; ++axis)
            if (level.dims[axis] != d[axis]) level = reduce(level, axis, d[axis]);
        auto* data = new unsigned char[level.values.size() * voxelBytes];
        storeAs(volume.type(), level.values, data);
        osg::ref_ptr<osg::Image> image = new osg::Image;
        image->setImage(d.x(), d.y(), d.z(), internalFormatFor(volume.type()), GL_RED, pixelTypeFor(volume.type()), data,
                        osg::Image::USE_NEW_DELETE, 1);
        out.push_back(image);
    }
    return out;
}

}  // namespace volren
