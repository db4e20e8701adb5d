#pragma once
#include "DicomSlice.h"

#include <string>
#include <vector>

namespace volren::dicom {

/// Finds the slices of one series for `path`: a directory (the series `seriesUid`, else the
/// one with the most slices, named in a notice) or one slice file (its own series, from the
/// files of its directory). Files that are not DICOM are skipped. Throws
/// std::runtime_error("path: reason") when there is nothing to read.
std::vector<DicomSlice> findSeries(const std::string& path, const std::string& seriesUid);

}  // namespace volren::dicom
