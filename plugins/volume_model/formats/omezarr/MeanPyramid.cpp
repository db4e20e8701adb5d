#include "MeanPyramid.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <type_traits>

namespace volren::omezarr {

namespace {

/// Halves one block of `in` (dims `d`) into `out` (dims `h`) by the mean of each 2x2x2 cell.
template <typename T>
void halveBlock(const std::uint8_t* inBytes, const osg::Vec3i& d, std::uint8_t* outBytes, const osg::Vec3i& h)
{
    const auto at = [](const std::uint8_t* base, std::size_t i) {
        T v;
        std::memcpy(&v, base + i * sizeof(T), sizeof(T));
        return double(v);
    };
    // Each output voxel covers input 2i and 2i+1 along a halved axis (2i+1 only when it exists),
    // input i along an axis of one voxel.
    const int fx = d.x() > 1 ? 2 : 1, fy = d.y() > 1 ? 2 : 1, fz = d.z() > 1 ? 2 : 1;
    const std::size_t nx = std::size_t(d.x()), nxy = nx * std::size_t(d.y());
    std::size_t o = 0;
    for (int z = 0; z < h.z(); ++z)
        for (int y = 0; y < h.y(); ++y)
            for (int x = 0; x < h.x(); ++x, ++o) {
                double sum = 0.0;
                int count = 0;
                for (int k = z * fz; k < std::min(z * fz + fz, d.z()); ++k)
                    for (int j = y * fy; j < std::min(y * fy + fy, d.y()); ++j)
                        for (int i = x * fx; i < std::min(x * fx + fx, d.x()); ++i) {
                            sum += at(inBytes, std::size_t(k) * nxy + std::size_t(j) * nx + std::size_t(i));
                            ++count;
                        }
                const double mean = sum / count;
                const T value = std::is_floating_point_v<T> ? T(mean) : T(std::round(mean));
                std::memcpy(outBytes + o * sizeof(T), &value, sizeof(T));
            }
}

}  // namespace

osg::ref_ptr<Volume> halveByMean(const Volume& volume)
{
    const osg::Vec3i& d = volume.dims();
    const osg::Vec3i h((d.x() + 1) / 2, (d.y() + 1) / 2, (d.z() + 1) / 2);
    osg::ref_ptr<Volume> out = new Volume;
    out->allocate(volume.type(), h, volume.channels(), volume.frames());
    for (int t = 0; t < volume.frames(); ++t)
        for (int c = 0; c < volume.channels(); ++c) {
            const std::uint8_t* in = volume.block(c, t);
            std::uint8_t* o = out->block(c, t);
            switch (volume.type()) {
            case VoxelType::UInt8: halveBlock<std::uint8_t>(in, d, o, h); break;
            case VoxelType::Int8: halveBlock<std::int8_t>(in, d, o, h); break;
            case VoxelType::UInt16: halveBlock<std::uint16_t>(in, d, o, h); break;
            case VoxelType::Int16: halveBlock<std::int16_t>(in, d, o, h); break;
            case VoxelType::Float32: halveBlock<float>(in, d, o, h); break;
            }
        }
    const osg::Vec3d& s = volume.spacing();
    out->setSpacing(osg::Vec3d(s.x() * (d.x() > 1 ? 2.0 : 1.0), s.y() * (d.y() > 1 ? 2.0 : 1.0), s.z() * (d.z() > 1 ? 2.0 : 1.0)));
    out->setRescale(volume.rescaleSlope(), volume.rescaleIntercept());
    out->sourceFile = volume.sourceFile;
    out->dirty();
    return out;
}

}  // namespace volren::omezarr
