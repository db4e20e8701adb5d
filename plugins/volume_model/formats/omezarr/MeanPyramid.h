#pragma once
#include <volume_model/Volume.h>

namespace volren::omezarr {

/// The next coarser pyramid level of `volume`: every axis longer than one voxel halved (n
/// voxels become ceil(n / 2)), each new voxel the mean of the 2x2x2 voxels it covers (fewer at
/// an odd edge: the mean of those present), per block (channel, time point). Integer types are
/// rounded to the nearest value (halves away from zero), so the voxel type is kept; a NaN
/// among float voxels makes their mean NaN. Spacing doubles along halved axes; rescale kept.
osg::ref_ptr<Volume> halveByMean(const Volume& volume);

}  // namespace volren::omezarr
