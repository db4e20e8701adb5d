#pragma once
#include "FileVoxelType.h"
#include "Payload.h"

#include <volume_model/Volume.h>

#include <osg/Vec3d>
#include <osg/Vec3i>

namespace volren::rawvolume {

/// Everything a header says about a raw voxel payload; header readers fill it in.
struct PayloadLayout
{
    std::string name;                    ///< the header file, named in every message
    osg::Vec3i dims;                     ///< voxels along x, y, z (checked by Volume::checkedVoxelCount)
    int channels = 1;                    ///< values per voxel, interleaved in the file (fastest axis)
    int frames = 1;                      ///< time points, slowest axis
    FileVoxelType type = FileVoxelType::UInt8;  ///< stored value type
    bool bigEndian = false;              ///< byte order of multi-byte values
    osg::Vec3d spacing{1.0, 1.0, 1.0};   ///< must be positive and finite
    double slope = 1.0, intercept = 0.0; ///< data = stored * slope + intercept
    std::vector<PayloadPart> parts;      ///< where the bytes are
};

/// Reads the payload described by `layout` into a new Volume (straight into its buffer; one
/// extra buffer only for interleaved channels) with native byte order. Int32/UInt32 values are
/// kept as float32 when every value has |v| <= 2^24 (exact); otherwise the file is refused.
/// Opens the payload lazily instead (LazyOpening.h: option `lazy`, or more voxel bytes than
/// option ramBudgetMB=N, default a quarter of RAM) when it is uncompressed, in one data file, one
/// channel and time point, not int32/uint32: the voxels are then the LazyRawSource's preview
/// level (spacing scaled to the same box) and Volume::fullResolution() the source.
/// Throws std::runtime_error("name: reason").
osg::ref_ptr<Volume> readPayloadVolume(const PayloadLayout& layout, const osgDB::Options* options);

}  // namespace volren::rawvolume
