#pragma once
#include "PayloadVolume.h"

#include <string>

namespace volren::rawvolume {

/// Layout of a QVis/Erlangen `.dat` text header (ObjectFileName, Resolution, SliceThickness,
/// Format UCHAR/USHORT/FLOAT, ObjectModel I/RGB/RGBA); the raw file is little-endian.
PayloadLayout describeQvisFile(const std::string& path);

}  // namespace volren::rawvolume
