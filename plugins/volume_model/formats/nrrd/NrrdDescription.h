#pragma once
#include <PayloadVolume.h>

#include <string>

namespace volren::nrrd {

/// Layout of the NRRD file `path` (`.nrrd` attached or `.nhdr` detached header): dimension 3,
/// or 4 with a leading channel axis; types (u)char, (u)short, (u)int (as exact float32),
/// float; encodings raw and gzip; `spacings` or the lengths of `space directions`; data file
/// single, `LIST` or `pattern min max step`. `space origin` is ignored (volumes are placed by
/// their node). Throws std::runtime_error("path: reason").
rawvolume::PayloadLayout describeNrrdFile(const std::string& path);

}  // namespace volren::nrrd
