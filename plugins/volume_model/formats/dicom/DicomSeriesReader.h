#pragma once
#include "DicomSliceOrder.h"

#include <volume_model/Volume.h>

#include <osgDB/Options>

#include <string>

namespace volren::dicom {

/// Key of the osg::Matrixd user value on the Volume: voxel index (i, j, k) to patient
/// coordinates in mm (DICOM LPS), OSG row-vector convention: world = Vec3d(i, j, k) * matrix.
constexpr const char* voxelToWorldKey = "voxelToWorld";

/// Decodes the slices of `order` (any transfer syntax GDCM decodes) into one Volume:
/// 8/16-bit signed/unsigned kept, 32-bit integers widened to float32, rescale from
/// RescaleSlope/RescaleIntercept. Reports progress per slice to `options` and honours
/// cancellation. Throws std::runtime_error("name: reason").
osg::ref_ptr<Volume> readSeries(const SliceOrder& order, const std::string& name, const osgDB::Options* options);

}  // namespace volren::dicom
