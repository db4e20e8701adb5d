#pragma once
#include "NiftiByteSource.h"

#include <volume_model/Volume.h>

#include <string>

namespace volren::nifti {

/// Parses a single-file NIfTI-1 (`n+1`) or NIfTI-2 (`n+2`) volume, either byte order, from
/// `source`; stores the voxel-to-world matrix as a user value (NiftiOrientation.h). `name` is
/// used in messages. Throws std::runtime_error("name: reason") on bad input.
osg::ref_ptr<Volume> readNifti(const ByteSource& source, const std::string& name);

}  // namespace volren::nifti
