#pragma once
#include <functional>
#include <string>
#include <vector>

namespace volren::dicom {

/// Runs `step` on each of `files` in a child process first. Debian's GDCM 3.0 is built with its
/// asserts on and aborts the process on some malformed files (DicomStructure catches the known
/// kinds, not every one), so an abort in the child becomes an error here instead of ending the
/// program. Returns "" when every step finished, else "FILE: GDCM aborted reading it (...)".
/// Where fork() is not available the steps are not probed.
std::string probeInChild(const std::vector<std::string>& files, const std::function<void(const std::string&)>& step);

}  // namespace volren::dicom
