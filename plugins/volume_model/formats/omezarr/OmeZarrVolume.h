#pragma once
#include <volume_model/LengthUnit.h>
#include <volume_model/Volume.h>

#include <osgDB/Options>

#include <cstddef>
#include <string>

namespace volren::omezarr {

/// Key of the std::string user value: unit of the time axis ("second").
constexpr const char* timeUnitKey = "timeUnit";
/// Key of the double user value: time between frames (the time axis' scale).
constexpr const char* timeStepKey = "timeStep";
/// Key of the int user value: resolution levels of the image the volume was read from.
constexpr const char* levelCountKey = "omeZarrLevels";

/// Reads resolution level `level` (0 = finest) of the OME-Zarr image at `path` into a Volume:
/// every channel and time point becomes a block (c, t), spacing is the level's scale of x, y, z
/// in the file's unit (kept as given, as the other readers do; the unit is the spacingUnitKey
/// user value), scale and translation together are the `voxelToWorld` user value (osg::Matrixd,
/// source "ome-zarr") as in the NIfTI and DICOM readers. A level over Volume::maxVoxels is
/// refused with a message that names the finest level that fits (option level=N). Progress
/// per chunk goes to the LoadProgress in `options`. Throws std::runtime_error("file: reason").
osg::ref_ptr<Volume> readOmeZarrVolume(const std::string& path, std::size_t level, const osgDB::Options* options);

/// Bytes of level `level` of the image at `path`, all channels and time points (saturated at
/// 2^64 - 1): what readOmeZarrVolume would hold in memory.
std::uint64_t omeZarrLevelBytes(const std::string& path, std::size_t level);

/// Opens the image at `path` lazily (LazyOpening.h): Volume::fullResolution() is an
/// OmeZarrSource for channel 0, time point 0, and the voxels are its finest level (a file level or
/// a reduction of the coarsest) whose bytes fit `previewBudget` (decoded chunks cached up to
/// `cacheBudget` bytes), with spacing = level 0's world
/// size / its dims (so the box is level 0's exactly; the file's own scale of a coarse level may
/// differ slightly) and voxelToWorld placing its voxel centres in level 0's box. User values as
/// readOmeZarrVolume. An image with several channels or time points stays one block (a notice
/// says that only channel 0, time point 0 is read). Throws std::runtime_error("file: reason").
osg::ref_ptr<Volume> openOmeZarrVolumeLazily(const std::string& path, std::uint64_t previewBudget, std::uint64_t cacheBudget,
                                             const osgDB::Options* options);

}  // namespace volren::omezarr
