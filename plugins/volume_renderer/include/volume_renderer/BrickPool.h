#pragma once
// A volume's mip levels cut into bricks that live in a pool texture of bounded size and are
// found through a page table (VolumeStorage/bricked): how volumes larger than the GPU's budget
// or its largest 3D texture are drawn.
#include <volume_model/Volume.h>

#include <volume_renderer/MacrocellGrid.h>

#include <osg/Image>
#include <osg/Matrixd>
#include <osg/Texture3D>

#include <cstddef>
#include <functional>
#include <optional>
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

/// The layout of levels of `levelDims` (finest first; each level covering the same box, as a
/// BrickSource's levels) in bricks of `brickSize` voxels; throws std::invalid_argument for a
/// brick size below 2 or no levels.
BrickLayout brickLayout(const std::vector<osg::Vec3i>& levelDims, int brickSize);

/// A brick of one level.
struct BrickId
{
    int level = 0;
    osg::Vec3i brick;
    bool operator<(const BrickId& o) const
    {
        return level != o.level ? level < o.level
               : brick.z() != o.brick.z() ? brick.z() < o.brick.z()
               : brick.y() != o.brick.y() ? brick.y() < o.brick.y()
                                          : brick.x() < o.brick.x();
    }
    bool operator==(const BrickId& o) const { return level == o.level && brick == o.brick; }
};

/// Which bricks a frame wants in the pool.
struct BrickPlan
{
    int firstLevel = 0;  ///< the finest level asked for (the node's level of detail)
    int finest = -1;     ///< finest level whose wanted bricks all fit: the level the rays sample
    std::vector<BrickId> slotted;  ///< bricks that need a pool slot, coarsest level first
    /// Bricks of one value (no slot; the page entry holds the texel value).
    std::vector<std::pair<BrickId, float>> constant;
};

/// Whether a brick of a level may be seen (the view's frustum); every brick when empty.
using BrickVisibility = std::function<bool(int level, const osg::Vec3i& brick)>;
/// The bricks of `layout` (kept alive by the caller) that may be seen through the sides of the
/// view `textureToClip` (volume texture space -> clip space), each with its border; near and far
/// are not tested (OSG fits them after culling).
BrickVisibility brickVisibility(const BrickLayout& layout, const osg::Matrixd& textureToClip);
/// For a brick whose every sample the transfer function hides, the texel value its page entry
/// holds instead (a value the TF hides); nothing for a brick that may show or is not known.
using BrickHiding = std::function<std::optional<float>(int level, const osg::Vec3i& brick)>;

/// Plans a pool of `capacity` slots from the coarsest level to `firstLevel`, a level at a time
/// while all of its visible bricks that need a slot fit (the coarsest level is wanted whole, so a
/// sample anywhere finds a value). `ranges[level]` holds each brick's texel range with its border
/// (a MacrocellGrid with cells of brickSize and an apron of 1), or is empty where unknown (a lazy
/// source's level not in memory: every brick needs a slot until loaded). With `constantBricks`,
/// a brick of one value takes no slot, and so does a brick `hidden` gives a value for (listed
/// with the constant ones). Deterministic. Throws std::invalid_argument when not even the
/// coarsest level fits.
BrickPlan planBricks(const BrickLayout& layout, const std::vector<MacrocellGrid>& ranges, int firstLevel,
                     std::size_t capacity, bool constantBricks, const BrickVisibility& visible = {},
                     const BrickHiding& hidden = {});

/// Pool slots along x, y, z for up to `wanted` slots of `slotTexels` texels each within a 3D
/// texture of at most `maxTextureSize` texels per axis.
osg::Vec3i poolSlotsFor(std::size_t wanted, int slotTexels, int maxTextureSize);

/// What a bricked volume holds (volren render --stats).
struct BrickStatistics
{
    std::string volume;            ///< the Volume's name (its file)
    int levelSampled = 0;          ///< the finest level the plan holds whole: the level the rays read
    std::size_t resident = 0;      ///< bricks in the pool (all levels)
    std::size_t constant = 0;      ///< bricks of one value (no slot)
    std::size_t hidden = 0;        ///< bricks the transfer function hides (no slot; of `constant`)
    std::size_t missing = 0;       ///< bricks of finer levels asked for that the budget or the view left out
    std::size_t pending = 0;       ///< bricks the plan wants that are not in the pool yet (streaming)
    std::size_t loaded = 0;        ///< bricks read so far (from memory or the file)
    std::size_t uploaded = 0;      ///< bricks sent to the GPU so far
    std::size_t evicted = 0;       ///< bricks dropped from the pool for others so far
    std::size_t poolBytes = 0;     ///< GPU bytes of the pool
    std::size_t budgetBytes = 0;   ///< the budget the pool was made within
    std::size_t sourceBytes = 0;   ///< host RAM a lazy volume's source holds (0 for volumes in memory)
};

/// The state of a bricked volume a frame binds (BrickStreamer.h keeps it).
struct BrickedVolume
{
    BrickLayout layout;
    int firstLevel = 0;   ///< the node's level of detail
    int levelSampled = 0; ///< the plan's finest level: rays sample here and fall back to coarser bricks
    osg::Vec3i poolTexels;                   ///< size of the pool texture
    osg::ref_ptr<osg::Texture3D> pool;       ///< the volume's texel format (16-bit for `wide` 8-bit)
    osg::ref_ptr<osg::Texture3D> pageTable;  ///< RGBA32F, nearest, read with texelFetch
};

}  // namespace volren
