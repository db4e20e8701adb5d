#pragma once
// The voxels of a volume's resolution levels, read region by region on demand: how a volume
// larger than RAM is drawn (the renderer's brick loader reads from it on a background thread).
#include <volume_model/VoxelType.h>

#include <osg/Referenced>
#include <osg/Vec3d>
#include <osg/Vec3i>

#include <cstdint>
#include <string>

namespace volren {

/// Resolution levels of one volume (level 0 the file's full resolution, each next level about
/// half along each axis, down to a few voxels), each read by region. Thread-safe: read() may run
/// on several threads at once. A Volume opened lazily holds one coarse level of its source in
/// memory (Volume::fullResolution).
class BrickSource : public osg::Referenced
{
public:
    /// The file (or folder) read, for messages.
    virtual std::string file() const = 0;
    /// Stored voxel type of every level (the Volume's rescale applies).
    virtual VoxelType type() const = 0;
    /// Levels, finest first (>= 1).
    virtual int levelCount() const = 0;
    /// Voxels along x, y, z of `level`; each level covers the same box in the world.
    virtual osg::Vec3i levelDims(int level) const = 0;
    /// World size of one voxel of level 0.
    virtual osg::Vec3d spacing() const = 0;
    /// Reads voxels [origin, origin + size) of `level` (inside it) into `out`: size.x * size.y *
    /// size.z stored values, x fastest, host byte order. Throws std::runtime_error naming the
    /// file and the reason on a read error (a missing OME-Zarr chunk reads as the fill value).
    virtual void read(int level, const osg::Vec3i& origin, const osg::Vec3i& size, std::uint8_t* out) const = 0;
    /// Bytes the source holds in RAM itself (its in-memory coarse levels, chunk caches).
    virtual std::size_t residentBytes() const = 0;

protected:
    ~BrickSource() override = default;
};

}  // namespace volren
