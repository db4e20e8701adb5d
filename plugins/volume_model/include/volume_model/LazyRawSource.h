#pragma once
// The levels of an uncompressed voxel payload in a file larger than RAM: level 0 read with
// positioned reads, coarse levels computed once in a streaming pass and kept, the levels
// between computed from level 0 on demand.
#include <volume_model/BrickSource.h>

#include <osgDB/Options>

#include <cstdint>
#include <string>
#include <vector>

namespace volren {

/// BrickSource over raw voxels (one channel, one time point, x fastest) in one file. Levels
/// follow the renderer's mip rule (meanLevelDims, MeanReduction.h). Opening reads the file
/// once, slab by slab, and keeps levels previewLevel() .. 1x1x1 in RAM; level 0 is read with
/// pread on a descriptor opened once (not mapped, so RSS stays what the process holds); levels
/// 1 .. previewLevel() - 1 are reduced from the level-0 region they cover on each read.
class LazyRawSource : public BrickSource
{
public:
    /// Where and how the voxels are stored.
    struct Layout
    {
        std::string path;                   ///< the data file
        std::uint64_t offset = 0;           ///< byte of voxel (0, 0, 0)
        osg::Vec3i dims;                    ///< voxels along x, y, z
        VoxelType type = VoxelType::UInt8;  ///< stored type
        bool bigEndian = false;             ///< byte order of the file
        osg::Vec3d spacing{1.0, 1.0, 1.0};  ///< world size of one level-0 voxel
    };

    /// Largest volume opened (2^40 voxels); larger dims are refused.
    static constexpr std::uint64_t maxVoxels = std::uint64_t(1) << 40;

    /// Opens `layout.path` and computes the in-memory levels: the finest level whose bytes fit
    /// `previewBytes` (previewLevel()) and all coarser ones. Reports progress to the LoadProgress
    /// in `options` (when given). Throws std::runtime_error("path: reason") when the file cannot
    /// be opened, is shorter than the voxels, a read fails or the load is cancelled, and
    /// std::invalid_argument for non-positive dims or more than maxVoxels.
    explicit LazyRawSource(const Layout& layout, std::uint64_t previewBytes = std::uint64_t(64) << 20,
                           const osgDB::Options* options = nullptr);

    const Layout& layout() const { return _layout; }
    /// The finest level held in memory.
    int previewLevel() const { return _preview; }
    /// Level `level` when it is held in memory (level >= previewLevel()), else null.
    const std::uint8_t* residentLevel(int level) const;

    std::string file() const override { return _layout.path; }
    VoxelType type() const override { return _layout.type; }
    int levelCount() const override { return int(_levels.size()); }
    osg::Vec3i levelDims(int level) const override;
    osg::Vec3d spacing() const override { return _layout.spacing; }
    void read(int level, const osg::Vec3i& origin, const osg::Vec3i& size, std::uint8_t* out) const override;
    std::size_t residentBytes() const override;

protected:
    ~LazyRawSource() override;

private:
    /// Level-0 voxels [origin, origin + size) in host byte order.
    void readBase(const osg::Vec3i& origin, const osg::Vec3i& size, std::uint8_t* out) const;
    /// pread of exactly `bytes` at file byte `at`; throws on error or end of file.
    void readBytes(std::uint8_t* out, std::uint64_t bytes, std::uint64_t at) const;
    void computeResidentLevels(const osgDB::Options* options);

    Layout _layout;
    int _fd = -1;
    int _preview = 0;
    std::vector<std::vector<std::uint8_t>> _levels;  ///< per level: its voxels when resident, else empty
};

}  // namespace volren
