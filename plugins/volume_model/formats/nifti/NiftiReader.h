#pragma once
#include "NiftiByteSource.h"

#include <volume_model/Volume.h>

#include <cstdint>
#include <limits>
#include <string>

namespace volren::nifti {

/// `maxBytes` of a source whose length nothing bounds (e.g. a stream).
constexpr std::uint64_t unknownSize = std::numeric_limits<std::uint64_t>::max();

/// Parses a single-file NIfTI-1 (`n+1`) or NIfTI-2 (`n+2`) volume, either byte order, from
/// `source`; stores the voxel-to-world matrix as a user value (NiftiOrientation.h). `name` is
/// used in messages. `maxBytes` bounds what `source` can deliver, header included (the file
/// size, or the most a compressed file can expand to): a header whose voxel data cannot fit is
/// refused as truncated before the voxel buffer is allocated. Throws
/// std::runtime_error("name: reason") on bad input.
osg::ref_ptr<Volume> readNifti(const ByteSource& source, const std::string& name, std::uint64_t maxBytes = unknownSize);

}  // namespace volren::nifti
