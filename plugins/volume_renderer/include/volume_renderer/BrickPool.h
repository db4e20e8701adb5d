#pragma once
// A volume's mip levels cut into bricks that live in a pool texture of bounded size and are
// found through a page table (VolumeStorage/bricked): how volumes larger than the GPU's budget
// or its largest 3D texture are drawn.
#include <volume_model/Volume.h>

#include <volume_renderer/MacrocellGrid.h>

#include <osg/Image>
#include <osg/Texture3D>

#include <cstddef>
#include <string>
#include <vector>

namespace volren {

/// One mip level cut into bricks of BrickLayout::brickSize voxels (the last along an axis may be
/// smaller); its page entries start at z slice `tableZ` of the page table.
struct BrickLevel
{
    osg::Vec3i dims;    ///< voxels of the level (mipDims)
    osg::Vec3i bricks;  ///< bricks along x, y, z: ceil(dims / brickSize)
    int tableZ = 0;     ///< first z slice of its entries in the page table
};

/// How a volume is cut into bricks at every mip level.
struct BrickLayout
{
    int brickSize = 32;               ///< brick edge in voxels (without the one-voxel border)
    std::vector<BrickLevel> levels;   ///< level 0 (full resolution) down to the 1 x 1 x 1 level
    osg::Vec3i tableSize;             ///< page table texels: most bricks along x, along y; all along z
    /// Bricks of `level`.
    std::size_t brickCount(int level) const;
};

/// The layout of a volume of `dims` in bricks of `brickSize` voxels; throws std::invalid_argument
/// for a brick size below 2.
BrickLayout brickLayout(const osg::Vec3i& dims, int brickSize);

/// Page entry kinds (the w of an RGBA32F page table texel).
enum class PageEntry
{
    Missing = 0,   ///< not in the pool: the ray reads the next coarser level
    Resident = 1,  ///< xyz: the pool slot holding the brick and its border
    Constant = 2,  ///< x: the one texel value of the whole brick and its border (never resident)
};

/// Which bricks the pool holds.
struct BrickResidency
{
    BrickLayout layout;
    int firstLevel = 0;            ///< the finest level asked for (the node's level of detail)
    int finestComplete = -1;       ///< finest level whose bricks are all resident or constant
    osg::Vec3i slots;              ///< pool slots along x, y, z (a slot is brickSize + 2 texels wide)
    std::vector<float> pageTable;  ///< RGBA per entry, layout.tableSize texels, x fastest
    /// Per pool slot in use: the level and brick it holds.
    std::vector<std::pair<int, osg::Vec3i>> resident;
    std::size_t constant = 0;  ///< bricks of the levels made complete that need no slot
};

/// Fills a pool of `capacity` slots (arranged as `slots`) from the coarsest level to
/// `firstLevel`, a level at a time while all its non-constant bricks fit; `ranges[level]` holds
/// each brick's texel range with its border (a MacrocellGrid with cells of brickSize and an
/// apron of 1). With `constantBricks`, a brick of one value takes no slot (its page entry holds
/// the value). Deterministic: the same inputs give the same pool. Throws std::invalid_argument
/// when not even the coarsest level fits.
BrickResidency chooseResidency(const BrickLayout& layout, const std::vector<MacrocellGrid>& ranges, int firstLevel,
                               const osg::Vec3i& slots, std::size_t capacity, bool constantBricks = true);

/// Pool slots along x, y, z for up to `wanted` slots of `slotTexels` texels each within a 3D
/// texture of at most `maxTextureSize` texels per axis.
osg::Vec3i poolSlotsFor(std::size_t wanted, int slotTexels, int maxTextureSize);

/// What a bricked volume holds (volren render --stats).
struct BrickStatistics
{
    std::string volume;            ///< the Volume's name (its file)
    int levelSampled = 0;          ///< the finest level held whole: the level the rays read
    std::size_t resident = 0;      ///< bricks in the pool (all levels)
    std::size_t constant = 0;      ///< bricks of one value (no slot)
    std::size_t missing = 0;       ///< bricks of finer levels asked for that the budget left out
    std::size_t poolBytes = 0;     ///< GPU bytes of the pool
    std::size_t budgetBytes = 0;   ///< the budget the pool was made within
};

/// A volume in bricks: the pool and page table textures and what they hold.
struct BrickedVolume
{
    BrickResidency residency;
    osg::ref_ptr<osg::Texture3D> pool;       ///< the volume's texel format (16-bit for `wide` 8-bit)
    osg::ref_ptr<osg::Texture3D> pageTable;  ///< RGBA32F, nearest, read with texelFetch
    std::size_t poolBytes = 0;               ///< GPU bytes of the pool texture
    std::size_t budgetBytes = 0;             ///< the budget it was made within
    /// Its statistics, named `volume`.
    BrickStatistics statistics(const std::string& volume) const;
};

/// Block (0, 0) of `volume` from mip level `firstLevel` down, in bricks of `brickSize` voxels,
/// in a pool of at most `budgetBytes` and `maxTextureSize` texels per axis; `levelImages` are
/// levels 1, 2, ... (mipLevelImages, the whole chain). `wide`: 8-bit data in 16-bit texels.
BrickedVolume makeBrickedVolume(const Volume& volume, const std::vector<osg::ref_ptr<osg::Image>>& levelImages,
                                int firstLevel, int brickSize, std::size_t budgetBytes, int maxTextureSize, bool wide);

}  // namespace volren
