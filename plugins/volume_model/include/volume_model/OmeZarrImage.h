#pragma once
#include <volume_model/OmeZarrAttributes.h>
#include <volume_model/ZarrArray.h>

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace volren {

/// An OME-Zarr 0.4 image on disk: its metadata and one ZarrArray per resolution level (the LOD
/// pyramid, finest first), checked against each other on opening. Reads nothing but metadata;
/// voxels come chunk by chunk or region by region through level(i).
class OmeZarrImage
{
public:
    /// Opens `path`: an image group (`.zattrs` with multiscales), a bioformats2raw folder (its
    /// image "0"), or a bare zarr array (one level, axes [t] [c] z y x by dimension count).
    /// Throws std::runtime_error("file: reason"): missing or malformed metadata, a level whose
    /// dimension count differs from the axes, whose dtype differs from level 0's, whose time or
    /// channel count differs, or that is larger than the level before it along a space axis.
    explicit OmeZarrImage(const std::string& path);

    const std::string& path() const { return _path; }                   ///< the image group folder
    const OmeZarrAttributes& attributes() const { return _attributes; }  ///< axes, levels, omero
    std::size_t levelCount() const { return _levels.size(); }           ///< resolution levels (>= 1)
    const ZarrArray& level(std::size_t i) const;                         ///< level i's array (0 finest); throws std::out_of_range

    int timeAxis() const { return _time; }        ///< array dimension of time, or -1
    int channelAxis() const { return _channel; }  ///< array dimension of channels, or -1
    /// Array dimension of x (0), y (1) or z (2); -1 for z of a 2-D image.
    int spaceAxis(int xyz) const { return _space[std::size_t(xyz)]; }

    std::uint64_t frames() const;    ///< time points (1 without a time axis)
    std::uint64_t channels() const;  ///< channels (1 without a channel axis)
    /// Voxels along x, y, z of level `i` (z is 1 for a 2-D image).
    std::array<std::uint64_t, 3> size(std::size_t i) const;
    /// Voxel spacing along x, y, z of level `i` from its scale (z of a 2-D image: x's spacing).
    std::array<double, 3> spacing(std::size_t i) const;
    /// Position of voxel (0, 0, 0) of level `i` along x, y, z from its translation.
    std::array<double, 3> origin(std::size_t i) const;
    /// Unit of the space axes ("micrometer"), or "" when absent or when the axes disagree.
    std::string spaceUnit() const;
    /// Unit of the time axis, or "".
    std::string timeUnit() const;
    /// Time between frames of level `i` (the time axis' scale; 1 without a time axis).
    double timeStep(std::size_t i) const;

private:
    void checkLevels() const;

    std::string _path;
    OmeZarrAttributes _attributes;
    std::vector<std::unique_ptr<ZarrArray>> _levels;
    int _time = -1, _channel = -1;
    std::array<int, 3> _space{-1, -1, -1};
};

}  // namespace volren
