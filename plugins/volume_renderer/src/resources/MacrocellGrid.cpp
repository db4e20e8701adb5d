// The macrocell value-range grid of empty-space skipping, built in three separable passes
// (ranges along x, then y, then z), and its occupancy under a classification.
#include <volume_renderer/MacrocellGrid.h>
#include <volume_renderer/VolumeMipChain.h>
#include <volume_renderer/VolumeTextures.h>

#include <glm/gtc/packing.hpp>
#include <osg/Image>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>

namespace volren {

namespace {

template <typename T>
T storedAt(const std::uint8_t* data, std::size_t i)
{
    T v;
    std::memcpy(&v, data + i * sizeof(T), sizeof(T));
    return v;
}

/// Texel values of one x row of voxels.
void texelRow(const Volume& volume, std::size_t first, int count, std::vector<double>& row)
{
    for (int x = 0; x < count; ++x) row[std::size_t(x)] = texelValue(volume, first + std::size_t(x));
}

/// Cell range of voxel index span [c*size - apron, (c+1)*size - 1 + apron] clamped to [0, n).
std::pair<int, int> span(int c, int size, int apron, int n)
{
    return {std::max(0, c * size - apron), std::min(n - 1, (c + 1) * size - 1 + apron)};
}

}  // namespace

GridShape gridShapeFor(const osg::Vec3i& dims, int macrocellSize, int footprint, int lod)
{
    if (lod <= 0) return {macrocellSize, footprint};
    const double span = mipVoxelSpan(dims, lod);
    const long long size = std::min<long long>(1024, (long long)(macrocellSize) << std::min(lod, 20));
    return {int(std::max<long long>(size, macrocellSize)), int(std::ceil((footprint + 1.5) * span)) + 1};
}

double texelValue(VoxelType type, const std::uint8_t* d, std::size_t i)
{
    switch (type) {
    case VoxelType::UInt8: return storedAt<std::uint8_t>(d, i) / 255.0;
    case VoxelType::Int8: return std::max(storedAt<std::int8_t>(d, i) / 127.0, -1.0);
    case VoxelType::UInt16: return storedAt<std::uint16_t>(d, i) / 65535.0;
    case VoxelType::Int16: return std::max(storedAt<std::int16_t>(d, i) / 32767.0, -1.0);
    case VoxelType::Float32: return double(storedAt<float>(d, i));
    }
    return 0.0;
}

double texelValue(const Volume& volume, std::size_t i)
{
    return texelValue(volume.type(), volume.data(), i);
}

MacrocellGrid buildMacrocellGrid(const Volume& volume, int cellSize, int apron)
{
    if (cellSize < 1) throw std::invalid_argument("macrocell size must be at least one voxel");
    if (apron < 0) throw std::invalid_argument("macrocell apron must not be negative");
    const osg::Vec3i n = volume.dims();
    MacrocellGrid grid;
    grid.cellSize = cellSize;
    grid.apron = apron;
    grid.cells = osg::Vec3i((n.x() + cellSize - 1) / cellSize, (n.y() + cellSize - 1) / cellSize,
                            (n.z() + cellSize - 1) / cellSize);
    const int cx = grid.cells.x(), cy = grid.cells.y(), cz = grid.cells.z();
    constexpr float inf = std::numeric_limits<float>::infinity();

    // Pass x: per (cell x, voxel y, voxel z).
    std::vector<float> lx(std::size_t(cx) * n.y() * n.z(), inf), hx(lx.size(), -inf);
    std::vector<double> row(std::size_t(n.x()));
    for (int z = 0; z < n.z(); ++z)
        for (int y = 0; y < n.y(); ++y) {
            const std::size_t line = std::size_t(y) + std::size_t(n.y()) * std::size_t(z);
            texelRow(volume, line * std::size_t(n.x()), n.x(), row);
            for (int c = 0; c < cx; ++c) {
                const auto [a, b] = span(c, cellSize, apron, n.x());
                float lo = inf, hi = -inf;
                for (int x = a; x <= b; ++x) {
                    const double v = row[std::size_t(x)];
                    if (std::isnan(v)) continue;
                    lo = std::min(lo, float(v));
                    hi = std::max(hi, float(v));
                }
                lx[std::size_t(c) + std::size_t(cx) * line] = lo;
                hx[std::size_t(c) + std::size_t(cx) * line] = hi;
            }
        }
    // Pass y: per (cell x, cell y, voxel z).
    std::vector<float> ly(std::size_t(cx) * cy * n.z(), inf), hy(ly.size(), -inf);
    for (int z = 0; z < n.z(); ++z)
        for (int c = 0; c < cy; ++c) {
            const auto [a, b] = span(c, cellSize, apron, n.y());
            for (int x = 0; x < cx; ++x) {
                float& lo = ly[std::size_t(x) + std::size_t(cx) * (std::size_t(c) + std::size_t(cy) * std::size_t(z))];
                float& hi = hy[std::size_t(x) + std::size_t(cx) * (std::size_t(c) + std::size_t(cy) * std::size_t(z))];
                for (int y = a; y <= b; ++y) {
                    const std::size_t i = std::size_t(x) + std::size_t(cx) * (std::size_t(y) + std::size_t(n.y()) * std::size_t(z));
                    lo = std::min(lo, lx[i]);
                    hi = std::max(hi, hx[i]);
                }
            }
        }
    // Pass z: per cell.
    grid.lo.assign(std::size_t(cx) * cy * cz, inf);
    grid.hi.assign(grid.lo.size(), -inf);
    for (int c = 0; c < cz; ++c) {
        const auto [a, b] = span(c, cellSize, apron, n.z());
        for (int y = 0; y < cy; ++y)
            for (int x = 0; x < cx; ++x) {
                const std::size_t out = grid.index(x, y, c);
                for (int z = a; z <= b; ++z) {
                    const std::size_t i = std::size_t(x) + std::size_t(cx) * (std::size_t(y) + std::size_t(cy) * std::size_t(z));
                    grid.lo[out] = std::min(grid.lo[out], ly[i]);
                    grid.hi[out] = std::max(grid.hi[out], hy[i]);
                }
            }
    }
    return grid;
}

std::vector<std::uint8_t> occupancyOf(const MacrocellGrid& grid, const std::function<bool(double, double)>& mayShow,
                                      const std::function<bool(double, double)>& homogeneous)
{
    std::vector<std::uint8_t> out(grid.size(), 0);
    for (std::size_t i = 0; i < grid.size(); ++i) {
        const double lo = grid.lo[i], hi = grid.hi[i];
        if (!(lo <= hi) || !mayShow(lo, hi)) continue;
        out[i] = !homogeneous || homogeneous(lo, hi) ? 255 : occupiedVarying;
    }
    return out;
}

namespace {

/// Size of the texture of cells followed along x by their coarse level.
osg::Vec3i packedSize(const MacrocellGrid& grid)
{
    const int f = occupancyCoarseFactor;
    const osg::Vec3i c = grid.cells;
    return osg::Vec3i(c.x() + (c.x() + f - 1) / f, c.y(), c.z());
}

/// Calls visit(cell index, packed texel index, coarse packed texel index) for every cell.
template <typename Visit>
void forEachPackedCell(const MacrocellGrid& grid, const osg::Vec3i& size, Visit visit)
{
    const int f = occupancyCoarseFactor;
    const osg::Vec3i c = grid.cells;
    auto at = [&](int x, int y, int z) {
        return std::size_t(x) + std::size_t(size.x()) * (std::size_t(y) + std::size_t(size.y()) * std::size_t(z));
    };
    for (int z = 0; z < c.z(); ++z)
        for (int y = 0; y < c.y(); ++y)
            for (int x = 0; x < c.x(); ++x) visit(grid.index(x, y, z), at(x, y, z), at(c.x() + x / f, y / f, z / f));
}

}  // namespace

std::vector<std::uint8_t> occupancyTexels(const MacrocellGrid& grid, const std::vector<std::uint8_t>& occupancy,
                                          osg::Vec3i& size)
{
    if (occupancy.size() != grid.size()) throw std::invalid_argument("occupancy and macrocell grid differ in size");
    size = packedSize(grid);
    std::vector<std::uint8_t> texels(std::size_t(size.x()) * size.y() * size.z(), 0);
    forEachPackedCell(grid, size, [&](std::size_t cell, std::size_t texel, std::size_t coarse) {
        texels[texel] = occupancy[cell];
        texels[coarse] = std::max(texels[coarse], occupancy[cell]);
    });
    return texels;
}

std::vector<osg::Vec2f> rangeTexels(const MacrocellGrid& grid, osg::Vec3i& size)
{
    constexpr float inf = std::numeric_limits<float>::infinity();
    size = packedSize(grid);
    std::vector<osg::Vec2f> texels(std::size_t(size.x()) * size.y() * size.z(), osg::Vec2f(inf, -inf));
    forEachPackedCell(grid, size, [&](std::size_t cell, std::size_t texel, std::size_t coarse) {
        texels[texel] = osg::Vec2f(grid.lo[cell], grid.hi[cell]);
        texels[coarse] = osg::Vec2f(std::min(texels[coarse].x(), grid.lo[cell]), std::max(texels[coarse].y(), grid.hi[cell]));
    });
    return texels;
}

std::uint16_t halfBound(float v, bool upper)
{
    if (std::isnan(v)) return glm::packHalf1x16(upper ? std::numeric_limits<float>::infinity() : -std::numeric_limits<float>::infinity());
    std::uint16_t h = glm::packHalf1x16(v);  // nearest; out of range: infinite
    const float back = glm::unpackHalf1x16(h);
    if (upper ? back >= v : back <= v) return h;
    // One step of the half's magnitude towards the bound: its sign bit decides the direction.
    const bool negative = (h & 0x8000) != 0;
    if ((h & 0x7fff) == 0) return upper ? std::uint16_t(0x0001) : std::uint16_t(0x8001);  // past zero
    return (upper != negative) ? std::uint16_t(h + 1) : std::uint16_t(h - 1);
}

osg::ref_ptr<osg::Texture3D> makeRangeTexture(const MacrocellGrid& grid)
{
    osg::Vec3i size;
    const std::vector<osg::Vec2f> texels = rangeTexels(grid, size);
    osg::ref_ptr<osg::Image> image = new osg::Image;
    image->allocateImage(size.x(), size.y(), size.z(), GL_RG, GL_HALF_FLOAT);
    image->setInternalTextureFormat(GL_RG16F);
    auto* out = reinterpret_cast<std::uint16_t*>(image->data());
    for (std::size_t i = 0; i < texels.size(); ++i) {
        out[2 * i] = halfBound(texels[i].x(), false);
        out[2 * i + 1] = halfBound(texels[i].y(), true);
    }
    return makeTexture3D(image.get(), GL_RG16F, osg::Texture::NEAREST);
}

osg::ref_ptr<osg::Texture3D> makeOccupancyTexture(const MacrocellGrid& grid, const std::vector<std::uint8_t>& occupancy)
{
    osg::Vec3i size;
    const std::vector<std::uint8_t> texels = occupancyTexels(grid, occupancy, size);
    osg::ref_ptr<osg::Image> image = new osg::Image;
    image->allocateImage(size.x(), size.y(), size.z(), GL_RED, GL_UNSIGNED_BYTE);
    image->setInternalTextureFormat(GL_R8);
    std::copy(texels.begin(), texels.end(), image->data());
    return makeTexture3D(image.get(), GL_R8, osg::Texture::NEAREST);
}

}  // namespace volren
