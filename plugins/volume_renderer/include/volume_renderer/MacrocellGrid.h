#pragma once
#include <volume_model/Volume.h>

#include <osg/Texture3D>

#include <cstdint>
#include <functional>
#include <vector>

namespace volren {

/// The range of texel values (what the GPU's volume texture returns) in each macrocell of a
/// volume, widened by an apron of voxels so that every sample inside a cell reads only voxels
/// counted in the cell's range. Cell (x, y, z) holds voxels [x*cellSize, (x+1)*cellSize) along
/// x (and so on), i.e. texture coordinates [x*cellSize/dims.x, (x+1)*cellSize/dims.x).
struct MacrocellGrid
{
    int cellSize = 8;                 ///< cell edge in voxels
    int apron = 1;                    ///< voxels beyond the cell's own counted in its range
    osg::Vec3i cells = {};            ///< cells along x, y, z: ceil(dims / cellSize)
    std::vector<float> lo = {}, hi = {};  ///< per cell (x fastest): texel range; lo > hi: only NaN

    /// Index of cell (x, y, z) in lo and hi.
    std::size_t index(int x, int y, int z) const
    {
        return std::size_t(x) + std::size_t(cells.x()) * (std::size_t(y) + std::size_t(cells.y()) * std::size_t(z));
    }
    /// Number of cells.
    std::size_t size() const { return lo.size(); }
};

/// Edge and apron, in level-0 voxels, of the macrocells that serve a Reconstruction of
/// `footprint` sampling mip level `lod` of a volume of `dims`.
struct GridShape
{
    int cellSize = 8;
    int apron = 1;
};

/// At level 0: cells of `macrocellSize` voxels, the footprint as apron. At level L > 0 (one
/// voxel covering s level-0 voxels, VolumeMipChain.h): cells of macrocellSize level-L voxels
/// (at most 1024), and an apron of ceil((footprint + 1.5) s) + 1 level-0 voxels: a level-L
/// sample reads level-L voxels within footprint + 0.5 of its own, each an average of level-0
/// voxels within its box (widened by less than one voxel per level where a size was odd).
GridShape gridShapeFor(const osg::Vec3i& dims, int macrocellSize, int footprint, int lod);

/// Texel value the GPU reads for stored voxel `i` of `data` of `type`: unsigned integers / max,
/// signed integers / max clamped to -1 (SNORM), floats as stored.
double texelValue(VoxelType type, const std::uint8_t* data, std::size_t i);
/// The same for voxel `i` of block (0, 0) of `volume`.
double texelValue(const Volume& volume, std::size_t i);

/// The grid of block (0, 0) of `volume` with cells of `cellSize` voxels and `apron` voxels of
/// apron; NaN voxels are left out of the ranges (they classify to zero opacity), infinities kept.
/// Throws std::invalid_argument for a cell size below 1 or a negative apron.
MacrocellGrid buildMacrocellGrid(const Volume& volume, int cellSize, int apron);

/// Per cell 255 where `mayShow(lo, hi)` holds (a sample there may be visible), else 0. With
/// `homogeneous` (adaptive sampling), visible cells are 255 where it holds too, else 128.
std::vector<std::uint8_t> occupancyOf(const MacrocellGrid& grid, const std::function<bool(double, double)>& mayShow,
                                      const std::function<bool(double, double)>& homogeneous = {});

/// Occupancy texel of a visible cell in which the classification varies (adaptive sampling).
constexpr std::uint8_t occupiedVarying = 128;

/// Cells per coarse cell along each axis in the occupancy texture's second level.
constexpr int occupancyCoarseFactor = 4;

/// The occupancy texture's texels: the cells (x < cells.x), then along x the coarse level, each
/// coarse texel non-zero where any of its occupancyCoarseFactor^3 cells is.
std::vector<std::uint8_t> occupancyTexels(const MacrocellGrid& grid, const std::vector<std::uint8_t>& occupancy,
                                          osg::Vec3i& size);

/// The range texture's texels, (lo, hi) per cell in the layout of occupancyTexels: the cells,
/// then the coarse level (the smallest lo and largest hi of its cells).
std::vector<osg::Vec2f> rangeTexels(const MacrocellGrid& grid, osg::Vec3i& size);

/// The half float nearest to `v` on the side of a bound: not below it for an upper bound, not
/// above it for a lower one (infinite beyond the half range; NaN gives the empty bound).
std::uint16_t halfBound(float v, bool upper);

/// RG16F 3D texture of the grid's ranges with their coarse level (rangeTexels; nearest,
/// texelFetch), each lo rounded down and hi up to a half float, so the ranges still hold.
osg::ref_ptr<osg::Texture3D> makeRangeTexture(const MacrocellGrid& grid);

/// R8 3D texture of an occupancy with its coarse level (occupancyTexels: nearest filtering,
/// read with texelFetch).
osg::ref_ptr<osg::Texture3D> makeOccupancyTexture(const MacrocellGrid& grid, const std::vector<std::uint8_t>& occupancy);

}  // namespace volren
