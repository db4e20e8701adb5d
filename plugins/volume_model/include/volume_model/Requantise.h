#pragma once
#include <volume_model/Volume.h>

namespace volren {

/// `volume` stored as `type` (UInt8, UInt16 or Float32), e.g. to measure what texture precision
/// costs: Float32 keeps the data values; the integer types map the finite value range onto
/// their full range through the rescale slope and intercept (non-finite voxels become the
/// lowest value). Spacing and name are kept. Throws std::invalid_argument for other types.
osg::ref_ptr<Volume> requantise(const Volume& volume, VoxelType type);

}  // namespace volren
