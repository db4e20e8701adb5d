#pragma once
// The levels of one channel and time point of an OME-Zarr image, read region by region through
// a small cache of decoded chunks; levels below the file's coarsest are mean reductions of it.
#include <volume_model/BrickSource.h>
#include <volume_model/OmeZarrImage.h>

#include <osgDB/Options>

#include <atomic>
#include <cstdint>
#include <list>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

namespace volren {

/// BrickSource over an OME-Zarr image for channel `channel`, time point `frame`. Levels
/// 0 .. fileLevelCount() - 1 are the file's multiscale levels with their own dims (each covers
/// the image's box); when the coarsest is larger than 1x1x1 the levels continue with mean
/// reductions of it (meanLevelDims of its dims, MeanReduction.h) down to 1x1x1. Those reduced
/// levels are computed in one streaming pass when opening and kept in memory from the finest
/// one whose bytes fit `previewBytes` on; finer reduced levels (only when the coarsest file
/// level itself is large) are reduced from it on each read. Decoded chunks are kept in an LRU
/// cache of at most `cacheBytes` (0: none), shared by the reading threads.
class OmeZarrSource : public BrickSource
{
public:
    /// Default bound of the decoded-chunk cache.
    static constexpr std::size_t defaultCacheBytes = std::size_t(256) << 20;

    /// Opens `path` (see OmeZarrImage); progress of the reduction pass goes to the LoadProgress
    /// in `options`. Throws std::runtime_error("file: reason") for a bad image, a channel or
    /// time point it does not have, a level over 2^31 voxels along an axis, or a read error.
    explicit OmeZarrSource(const std::string& path, std::size_t cacheBytes = defaultCacheBytes,
                           std::uint64_t previewBytes = std::uint64_t(64) << 20, int channel = 0, int frame = 0,
                           const osgDB::Options* options = nullptr);

    const OmeZarrImage& image() const { return *_image; }
    int fileLevelCount() const { return int(_image->levelCount()); }  ///< levels stored in the file
    /// The zarr box (all array dimensions) of region [origin, origin + size) of file level
    /// `level` for this channel and time point.
    ZarrBox box(int level, const osg::Vec3i& origin, const osg::Vec3i& size) const;
    /// Chunks decoded so far (cache misses), for measuring the cache.
    std::uint64_t chunkDecodes() const { return _decodes.load(); }

    std::string file() const override { return _image->path(); }
    VoxelType type() const override { return _type; }
    int levelCount() const override { return int(_dims.size()); }
    osg::Vec3i levelDims(int level) const override;
    osg::Vec3d spacing() const override;
    void read(int level, const osg::Vec3i& origin, const osg::Vec3i& size, std::uint8_t* out) const override;
    std::size_t residentBytes() const override;

protected:
    ~OmeZarrSource() override;

private:
    using Chunk = std::shared_ptr<const std::vector<std::uint8_t>>;
    using ChunkKey = std::pair<int, std::vector<std::uint64_t>>;

    /// Decoded chunk `index` of file level `level`, from the cache when it is there.
    Chunk chunk(int level, const std::vector<std::uint64_t>& index) const;
    void readFileRegion(int level, const osg::Vec3i& origin, const osg::Vec3i& size, std::uint8_t* out) const;
    void reduceCoarsestLevel(std::uint64_t previewBytes, const osgDB::Options* options);

    std::unique_ptr<OmeZarrImage> _image;
    int _channel = 0, _frame = 0;
    VoxelType _type = VoxelType::UInt8;
    std::vector<osg::Vec3i> _dims;                   ///< per level
    std::vector<std::vector<std::uint8_t>> _reduced;  ///< per level: the voxels of a resident reduced level, else empty

    std::size_t _cacheBytes = 0;
    mutable std::mutex _cacheMutex;
    mutable std::list<std::pair<ChunkKey, Chunk>> _lru;  ///< most recently used first
    mutable std::map<ChunkKey, std::list<std::pair<ChunkKey, Chunk>>::iterator> _cached;
    mutable std::size_t _cachedBytes = 0;
    mutable std::atomic<std::uint64_t> _decodes{0};
};

}  // namespace volren
