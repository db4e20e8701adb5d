#pragma once
#include <cstddef>
#include <functional>
#include <string>

namespace volren::nifti {

/// Reads up to `size` bytes into `dst`; returns the count read (less at end of data), or -1
/// on a stream error (then `error` says why).
using ByteSource = std::function<long long(void* dst, std::size_t size, std::string& error)>;

/// Reads exactly `size` bytes or throws std::runtime_error("name: truncated: what needs ...").
void readExactly(const ByteSource& source, void* dst, std::size_t size, const std::string& name, const char* what);

}  // namespace volren::nifti
