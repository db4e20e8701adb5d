#pragma once
#include <volume_model/Volume.h>

#include <osgDB/Options>

#include <cstddef>
#include <string>

namespace volren::omezarr {

/// Key of the std::string user value: unit of the spacing as the file names it ("micrometer").
constexpr const char* spacingUnitKey = "spacingUnit";
/// Key of the std::string user value: unit of the time axis ("second").
constexpr const char* timeUnitKey = "timeUnit";
/// Key of the double user value: time between frames (the time axis' scale).
constexpr const char* timeStepKey = "timeStep";
/// Key of the int user value: resolution levels of the image the volume was read from.
constexpr const char* levelCountKey = "omeZarrLevels";

/// Reads resolution level `level` (0 = finest) of the OME-Zarr image at `path` into a Volume:
/// every channel and time point becomes a block (c, t), spacing is the level's scale of x, y, z
/// in the file's unit (kept as given, as the other readers do; the unit is the spacingUnit user
/// value), scale and translation together are the `voxelToWorld` user value (osg::Matrixd,
/// source "ome-zarr") as in the NIfTI and DICOM readers. A level over Volume::maxVoxels is
/// refused with a message that names the finest level that fits (option level=N). Progress
/// per chunk goes to the LoadProgress in `options`. Throws std::runtime_error("file: reason").
osg::ref_ptr<Volume> readOmeZarrVolume(const std::string& path, std::size_t level, const osgDB::Options* options);

}  // namespace volren::omezarr
