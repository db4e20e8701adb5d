#pragma once
#include <volume_model/BrickSource.h>
#include <volume_model/Histogram.h>
#include <volume_model/VoxelType.h>

#include <osg/Object>
#include <osg/ref_ptr>
#include <osg/Vec3d>
#include <osg/Vec3f>
#include <osg/Vec3i>

#include <cstdint>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace volren {

/// What a file says about showing one of its channels (ImageJ hyperstack LUTs and display
/// ranges, OME-Zarr omero channels); every part optional.
struct ChannelHint
{
    std::string name;               ///< the channel's label; empty when the file gives none
    std::vector<osg::Vec3f> colours;  ///< its colour table from dark to bright, [0, 1]; empty: none
    bool hasWindow = false;         ///< whether `low`, `high` hold its display range
    double low = 0.0, high = 0.0;   ///< display range in data values
    bool visible = true;            ///< shown by default
};

/// A scalar voxel grid: stored values, geometry and the mapping to data units. No GL.
/// Voxel (i,j,k) is at index i + dims.x*(j + dims.y*k); data value = stored*slope + intercept.
/// Files with several channels (multi-channel confocal stacks) or time points keep them all:
/// the voxels are channels() x frames() blocks of dims, block (c, t) at index t*channels() + c;
/// data() is block (0, 0); a VolumeNode shows the blocks of its channels at its time point.
class Volume : public osg::Object
{
public:
    Volume();
    Volume(const Volume& other, const osg::CopyOp& copyop = osg::CopyOp::SHALLOW_COPY);
    META_Object(volren, Volume)

    /// Largest number of voxels accepted (2^34); larger requests are refused, not attempted.
    static constexpr std::uint64_t maxVoxels = std::uint64_t(1) << 34;

    /// Allocates zeroed voxels for `channels` x `frames` blocks of `dims`; throws
    /// std::invalid_argument for non-positive or too large dims or counts.
    void allocate(VoxelType type, const osg::Vec3i& dims, int channels = 1, int frames = 1);
    /// Takes ownership of `bytes` as the voxels (no copy); throws std::invalid_argument when
    /// dims or counts are invalid or bytes.size() != total voxel count * voxel size.
    void assign(VoxelType type, const osg::Vec3i& dims, std::vector<std::uint8_t>&& bytes, int channels = 1,
                int frames = 1);
    /// Voxel count of `blocks` blocks of `dims`, or an exception naming the problem
    /// (non-positive, over maxVoxels in all).
    static std::uint64_t checkedVoxelCount(const osg::Vec3i& dims, std::uint64_t blocks = 1);

    VoxelType type() const { return _type; }          ///< stored voxel type
    const osg::Vec3i& dims() const { return _dims; }  ///< voxels along x, y, z
    std::size_t voxelCount() const;                    ///< dims.x * dims.y * dims.z (one block)
    int channels() const { return _channels; }         ///< channels per time point (>= 1)
    int frames() const { return _frames; }             ///< time points (>= 1)
    std::size_t totalVoxelCount() const { return voxelCount() * std::size_t(_channels) * std::size_t(_frames); }
    std::size_t byteSize() const { return _data.size(); }  ///< bytes of voxel storage (all blocks)
    const std::uint8_t* data() const { return _data.data(); }  ///< raw stored voxels of block (0, 0)
    std::uint8_t* data() { return _data.data(); }  ///< writable voxels; call dirty() after writing
    /// Raw stored voxels of channel `channel` at time point `frame`; throws std::out_of_range.
    const std::uint8_t* block(int channel, int frame = 0) const;
    std::uint8_t* block(int channel, int frame = 0);  ///< writable block; call dirty() after writing

    /// World size of one voxel along x, y, z (positive, finite).
    const osg::Vec3d& spacing() const { return _spacing; }
    /// Sets the spacing; throws std::invalid_argument unless all components are positive and finite.
    void setSpacing(const osg::Vec3d& spacing);
    /// Smallest component of the spacing (of the full resolution for a volume opened lazily):
    /// the reference segment length of TF opacity and the base of the sample distance.
    double minSpacing() const;
    /// World size of the whole box: dims * spacing.
    osg::Vec3d worldSize() const;

    /// Linear map from stored values to data units (e.g. NIfTI scl_slope/scl_inter).
    void setRescale(double slope, double intercept);
    double rescaleSlope() const { return _slope; }          ///< data = stored*slope + intercept
    double rescaleIntercept() const { return _intercept; }  ///< data = stored*slope + intercept

    /// Stored value of voxel index `i` over all blocks (no rescale).
    double storedValue(std::size_t i) const;
    /// Data value of voxel index `i` (after rescale).
    double value(std::size_t i) const { return storedValue(i) * _slope + _intercept; }
    /// Data value at voxel (x,y,z).
    double value(int x, int y, int z) const;

    /// Smallest and largest finite data values of all blocks (NaN and Inf voxels are ignored).
    std::pair<double, double> valueRange() const;
    /// Number of NaN or Inf voxels.
    std::uint64_t nonFiniteCount() const;
    /// Histogram of finite data values over valueRange() with `bins` bins (cached per bin count).
    Histogram histogram(std::size_t bins = 256) const;

    /// File this volume was read from (empty when built in memory).
    std::string sourceFile;
    /// How the file shows each channel, where it says (index = channel; may be shorter, or empty).
    std::vector<ChannelHint> channelHints;

    /// Where the finer levels of a volume opened lazily live (files larger than the RAM budget):
    /// this Volume's voxels are then level `fullResolutionLevel()` of the source, a preview that
    /// statistics, histograms and the CPU reference use, while the renderer reads bricks of every
    /// level from the source. Null for a volume held whole in memory.
    const BrickSource* fullResolution() const { return _fullResolution.get(); }
    /// Which level of fullResolution() these voxels are (0 for a volume held whole).
    int fullResolutionLevel() const { return _fullResolutionLevel; }
    /// Attaches `source` whose level `level` these voxels are; throws std::invalid_argument when
    /// the source's level dims, type or world size disagree with this volume's.
    void setFullResolution(const BrickSource* source, int level);
    /// Voxels along x, y, z at full resolution (the source's level 0, or dims()).
    osg::Vec3i fullDims() const;

    /// Marks voxels or mapping as changed: drops cached statistics, bumps the modified count.
    void dirty();
    /// Incremented on every change; the renderer re-uploads when it differs from its copy.
    unsigned int modifiedCount() const { return _modifiedCount; }

private:
    void computeStatistics() const;

    VoxelType _type = VoxelType::UInt8;
    osg::Vec3i _dims{0, 0, 0};
    int _channels = 1, _frames = 1;
    osg::Vec3d _spacing{1.0, 1.0, 1.0};
    double _slope = 1.0;
    double _intercept = 0.0;
    std::vector<std::uint8_t> _data;
    unsigned int _modifiedCount = 0;
    osg::ref_ptr<const BrickSource> _fullResolution;
    int _fullResolutionLevel = 0;

    struct Statistics
    {
        double minStored = 0.0, maxStored = 0.0;
        std::uint64_t nonFinite = 0;
    };
    mutable std::mutex _statsMutex;
    mutable std::optional<Statistics> _stats;
    mutable std::optional<Histogram> _histogram;
};

}  // namespace volren
