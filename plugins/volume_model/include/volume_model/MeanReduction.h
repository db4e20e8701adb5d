#pragma once
// The overlap-weighted mean that makes a volume's coarser levels: the rule of the renderer's mip
// chain (volume_renderer's VolumeMipChain), kept in the model so that levels computed from a
// file (LazyRawSource, OmeZarrSource) equal the levels the renderer would compute in memory.
#include <volume_model/VoxelType.h>

#include <osg/Vec3i>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace volren {

/// Voxels of level `level` of a volume of `dims`: max(1, dims >> level) per axis.
osg::Vec3i meanLevelDims(const osg::Vec3i& dims, int level);
/// Levels from `dims` down to 1x1x1, both included (1 for a single voxel).
int meanLevelCount(const osg::Vec3i& dims);

/// The input voxels each output voxel averages when `n` voxels along an axis become `size`:
/// output j covers [j r, (j+1) r), r = n / size, each input voxel weighted by its overlap.
struct MeanTaps
{
    struct Tap
    {
        int input;      ///< input voxel index
        double weight;  ///< its overlap with the output voxel's box (> 0)
    };
    std::vector<std::size_t> begin;  ///< taps of output j: taps[begin[j]] .. taps[begin[j + 1] - 1], inputs ascending
    std::vector<Tap> taps;

    int first(int j) const { return taps[begin[std::size_t(j)]].input; }     ///< first input of output j
    int last(int j) const { return taps[begin[std::size_t(j) + 1] - 1].input; }  ///< last input of output j
};
/// Taps of reducing `n` voxels to `size` (1 <= size <= n).
MeanTaps meanTaps(int n, int size);

/// Stored values of `type` (host byte order) to float.
void storedToFloat(VoxelType type, const std::uint8_t* in, std::size_t count, float* out);
/// Floats to stored values of `type`: integers rounded (halves away from zero) and clamped to
/// the type's range (NaN becomes 0), float32 as is.
void floatToStored(VoxelType type, const float* in, std::size_t count, std::uint8_t* out);

/// The next level of `values` (a grid of `dims`, x fastest) in float: reduced along x, then y,
/// then z to meanLevelDims(dims, 1), each output the overlap-weighted mean of its inputs (sums
/// in double), NaN inputs left out (all NaN: NaN).
std::vector<float> meanNextLevel(const std::vector<float>& values, const osg::Vec3i& dims);

/// Computes a region of a coarser level from a base level streamed one z slice at a time,
/// level by level (each level: x and y per slice, then z across slices), with the exact
/// arithmetic of meanNextLevel: memory is a few slices per level, never a level whole.
class MeanReductionStream
{
public:
    /// Receives each finished z slice of level 1..lastLevel: level, z (in that level), and the
    /// region's regionSize(level).x * regionSize(level).y values, x fastest.
    using Sink = std::function<void(int level, int z, const float* slice)>;

    /// Levels 1..lastLevel of a base of `baseDims` (level l of dims meanLevelDims(baseDims, l)),
    /// for the region [origin, origin + size) of lastLevel (inside it).
    MeanReductionStream(const osg::Vec3i& baseDims, int lastLevel, const osg::Vec3i& origin, const osg::Vec3i& size);
    ~MeanReductionStream();
    MeanReductionStream(const MeanReductionStream&) = delete;
    MeanReductionStream& operator=(const MeanReductionStream&) = delete;

    /// Region of level `level` (0 = base .. lastLevel) the stream reads or computes.
    const osg::Vec3i& regionOrigin(int level) const { return _origins[std::size_t(level)]; }
    const osg::Vec3i& regionSize(int level) const { return _sizes[std::size_t(level)]; }  ///< see regionOrigin

    /// Feeds the next z slice of the base region (regionSize(0).x * regionSize(0).y values, the
    /// slices in order from regionOrigin(0).z); calls `sink` for every slice it finishes.
    void push(const float* slice, const Sink& sink);

private:
    struct Stage;
    void feed(std::size_t stage, const float* slice, const Sink& sink);

    std::vector<osg::Vec3i> _origins, _sizes;
    std::vector<Stage> _stages;
};

}  // namespace volren
