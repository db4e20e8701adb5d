#pragma once
#include <volume_model/Volume.h>

#include <cstddef>
#include <functional>
#include <string>

namespace volren::nifti {

/// Reads up to `size` bytes into `dst`; returns the count read (less at end of data), or -1
/// on a stream error (then `error` says why).
using ByteSource = std::function<long long(void* dst, std::size_t size, std::string& error)>;

/// Parses a single-file NIfTI-1 volume (`n+1` magic, either byte order) from `source`.
/// `name` is used in messages. Throws std::runtime_error("name: reason") on bad input.
osg::ref_ptr<Volume> readNifti1(const ByteSource& source, const std::string& name);

}  // namespace volren::nifti
