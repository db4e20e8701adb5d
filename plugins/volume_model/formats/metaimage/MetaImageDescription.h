#pragma once
#include <PayloadVolume.h>

#include <string>

namespace volren::metaimage {

/// Layout of the MetaImage file `path` (`.mhd` with ElementDataFile = FILE, LIST or
/// `pattern min max step`, `.mha` with LOCAL data): NDims 3 (4: time points),
/// ElementNumberOfChannels, DimSize, ElementSpacing (else ElementSize), ElementType
/// MET_(U)CHAR, MET_(U)SHORT, MET_FLOAT, MET_(U)INT as exact float32, byte order MSB flags,
/// CompressedData (zlib) with optional CompressedDataSize, HeaderSize. Throws
/// std::runtime_error("path: reason").
rawvolume::PayloadLayout describeMetaImageFile(const std::string& path);

}  // namespace volren::metaimage
